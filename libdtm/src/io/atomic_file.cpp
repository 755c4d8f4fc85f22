// SPDX-License-Identifier: MIT
// Atomic outputs. Every writer writes to a hidden temporary sibling of the target,
//
//     out/tin.ply   <-   out/.tin.tmp-<pid>-<n>.ply
//
// and commit() renames it over the target. rename(2) within one directory is atomic on POSIX file
// systems, so a reader sees either the old file or the complete new one, never a partial file, and
// a failed or cancelled run leaves an existing target untouched. The temporary keeps the target's
// extension at the end because GDAL picks drivers by extension (a shapefile must end in .shp).
// Multi-file formats write companions next to the temporary with the same stem (.shx, .dbf, .prj);
// commit() renames each to the target's stem with its own extension, the main file last.
//
// Before the renames, commit() flushes the temporaries to the disk (fsync) and afterwards the
// folder, so that a crash of the machine, not only of the process, keeps old or new.
// AtomicDirectory (atomic_directory.cpp) does the same for a whole folder.
#include "dtm/io/atomic_file.hpp"

#include <algorithm>
#include <string>
#include <system_error>

#include "detail/durable.hpp"
#include "dtm/core/error.hpp"

namespace dtm::io {
namespace fs = std::filesystem;

namespace {

/// Stem of the temporary: ".<target stem>.tmp-<pid>-<n>".
std::string temp_stem(const fs::path& target) { return detail::temp_name(target.stem().string()); }

/// Files next to @p temp named "<temp stem>.<anything>" other than @p temp itself, where the temp
/// stem is the temporary's name without the target's extension.
std::vector<fs::path> companions_of(const fs::path& temp, const fs::path& target) {
    const std::string name = temp.filename().string();
    const std::string prefix =
        name.substr(0, name.size() - target.extension().string().size()) + ".";
    std::vector<fs::path> found;
    std::error_code ec;
    for (fs::directory_iterator it(detail::parent_folder(temp), ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string candidate = it->path().filename().string();
        if (candidate != name && candidate.starts_with(prefix)) found.push_back(it->path());
    }
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace

AtomicOutput::AtomicOutput(fs::path target) : target_(std::move(target)) {
    std::error_code ec;
    const fs::path directory = detail::parent_folder(target_);
    if (!fs::is_directory(directory, ec)) {
        throw UsageError("cannot write " + target_.string() + ": directory " + directory.string() +
                         " does not exist");
    }
    if (fs::is_directory(target_, ec)) {
        throw UsageError("cannot write " + target_.string() + ": it is a directory");
    }
    temp_ = directory / (temp_stem(target_) + target_.extension().string());
}

AtomicOutput::~AtomicOutput() {
    if (committed_) return;
    std::error_code ec;
    for (const fs::path& companion : companions_of(temp_, target_)) fs::remove(companion, ec);
    fs::remove(temp_, ec);
}

void AtomicOutput::commit() {
    if (committed_) return;
    std::error_code ec;
    if (!fs::exists(temp_, ec)) {
        throw Error("cannot write " + target_.string() + ": the writer produced no file");
    }
    const fs::path target_directory = detail::parent_folder(target_);
    const std::string target_stem = target_.stem().string();
    const std::size_t prefix_size =
        temp_.filename().string().size() - target_.extension().string().size() + 1;
    const std::vector<fs::path> companions = companions_of(temp_, target_);
    for (const fs::path& companion : companions) detail::sync_path(companion);
    detail::sync_path(temp_);
    for (const fs::path& companion : companions) {
        const std::string suffix = companion.filename().string().substr(prefix_size - 1);
        detail::rename_path(companion, target_directory / (target_stem + suffix));
    }
    detail::rename_path(temp_, target_);
    committed_ = true;
    detail::sync_path(target_directory);
}

}  // namespace dtm::io
