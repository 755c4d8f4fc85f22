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
// AtomicDirectory stages a folder the same way: a hidden sibling folder receives every file,
// commit() renames them into the target folder one by one (all renames within one directory
// tree, so each is atomic) and removes the staging folder.
#include "dtm/io/atomic_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <string>
#include <system_error>

#include "dtm/core/error.hpp"

namespace dtm::io {
namespace fs = std::filesystem;

namespace {

fs::path directory_of(const fs::path& target) {
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

/// ".<name>.tmp-<pid>-<n>", n counting up in this process.
std::string temp_name(const std::string& name) {
    static std::atomic<unsigned long> counter{0};
    return "." + name + ".tmp-" + std::to_string(::getpid()) + '-' +
           std::to_string(counter.fetch_add(1));
}

/// Stem of the temporary: ".<target stem>.tmp-<pid>-<n>".
std::string temp_stem(const fs::path& target) { return temp_name(target.stem().string()); }

/// Files next to @p temp named "<temp stem>.<anything>" other than @p temp itself, where the temp
/// stem is the temporary's name without the target's extension.
std::vector<fs::path> companions_of(const fs::path& temp, const fs::path& target) {
    const std::string name = temp.filename().string();
    const std::string prefix =
        name.substr(0, name.size() - target.extension().string().size()) + ".";
    std::vector<fs::path> found;
    std::error_code ec;
    for (fs::directory_iterator it(directory_of(temp), ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string candidate = it->path().filename().string();
        if (candidate != name && candidate.starts_with(prefix)) found.push_back(it->path());
    }
    std::sort(found.begin(), found.end());
    return found;
}

void rename_or_throw(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec) throw Error("cannot write " + to.string() + ": " + ec.message());
}

}  // namespace

AtomicOutput::AtomicOutput(fs::path target) : target_(std::move(target)) {
    std::error_code ec;
    const fs::path directory = directory_of(target_);
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
    const fs::path target_directory = directory_of(target_);
    const std::string target_stem = target_.stem().string();
    const std::size_t prefix_size =
        temp_.filename().string().size() - target_.extension().string().size() + 1;
    for (const fs::path& companion : companions_of(temp_, target_)) {
        const std::string suffix = companion.filename().string().substr(prefix_size - 1);
        rename_or_throw(companion, target_directory / (target_stem + suffix));
    }
    rename_or_throw(temp_, target_);
    committed_ = true;
}

AtomicDirectory::AtomicDirectory(fs::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
    std::error_code ec;
    if (fs::exists(target_, ec) && !fs::is_directory(target_, ec)) {
        throw UsageError("cannot write into " + target_.string() + ": it is a file, not a folder");
    }
    const fs::path parent = directory_of(target_);
    staging_ = parent / temp_name(target_.filename().string());
    fs::create_directories(parent, ec);
    if (!fs::create_directory(staging_, ec) || ec) {
        throw Error("cannot create the temporary folder " + staging_.string() + ": " +
                    ec.message());
    }
}

AtomicDirectory::~AtomicDirectory() {
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

fs::path AtomicDirectory::add(const std::string& name) {
    if (!contains(name)) files_.push_back(name);
    return staging_ / name;
}

bool AtomicDirectory::contains(const std::string& name) const noexcept {
    return std::find(files_.begin(), files_.end(), name) != files_.end();
}

void AtomicDirectory::commit() {
    if (committed_) return;
    std::error_code ec;
    fs::create_directories(target_, ec);
    if (ec) throw Error("cannot create " + target_.string() + ": " + ec.message());
    for (const std::string& name : files_) {
        fs::create_directories((target_ / name).parent_path(), ec);  // "volume/volume.json"
        fs::rename(staging_ / name, target_ / name, ec);
        if (ec) {
            throw Error("cannot move " + name + " into " + target_.string() + ": " + ec.message());
        }
    }
    committed_ = true;
    fs::remove_all(staging_, ec);
}

}  // namespace dtm::io
