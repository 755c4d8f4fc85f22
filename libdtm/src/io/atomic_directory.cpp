// SPDX-License-Identifier: MIT
// A folder of products switched into place in one step. The products are written into a hidden
// sibling of the target, then commit()
//
//   1. drops unrecorded files from the staging folder and hard-links the target's other files
//      into it (copies where hard links fail), so that the new folder is the whole new state;
//   2. fsyncs every file and folder in it;
//   3. swaps it with the target: renameat2(RENAME_EXCHANGE), one atomic step, and removes the
//      old folder (now under the staging name) and fsyncs the parent.
//
// A process killed at any point leaves the target as the complete old folder (before 3) or the
// complete new one (after 3); the leftover staging folder is removed by the next run.
// Fallback where the file system refuses the exchange (EINVAL, ENOSYS, EOPNOTSUPP): the rename
// pair target -> ".<name>.old", staging -> target. Between the two there is no target, only the
// complete old folder under ".<name>.old"; recover_directory() renames it back (the next run does
// so before anything else). A target that does not exist yet is a single rename.
#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "detail/durable.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"

namespace dtm::io {
namespace fs = std::filesystem;

namespace {

fs::path backup_of(const fs::path& target) {
    return detail::parent_folder(target) / ("." + target.filename().string() + ".old");
}

bool process_gone(long pid) {
    return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

/// Whether the staging folder's entry @p name is, or holds, a recorded file ("volume" holds
/// "volume/volume.json").
bool recorded(const std::vector<std::string>& files, const std::string& name) {
    return std::any_of(files.begin(), files.end(), [&name](const std::string& file) {
        return file == name || (file.size() > name.size() && file[name.size()] == '/' &&
                                file.compare(0, name.size(), name) == 0);
    });
}

/// Step 1: the staging folder becomes the complete new state of the target.
void carry_over(const fs::path& target,
                const fs::path& staging,
                const std::vector<std::string>& files) {
    std::error_code ec;
    for (fs::directory_iterator it(staging, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!recorded(files, name)) fs::remove_all(it->path(), ec);
    }
    for (const std::string& name : files) {
        if (!fs::exists(staging / name, ec)) {
            throw Error("cannot move " + name + " into " + target.string() +
                        ": the writer produced no file");
        }
    }
    if (!fs::is_directory(target, ec)) return;
    for (fs::directory_iterator it(target, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path to = staging / it->path().filename();
        if (fs::exists(fs::symlink_status(to, ec))) continue;
        constexpr auto both = fs::copy_options::recursive | fs::copy_options::copy_symlinks;
        std::error_code link_ec;
        fs::copy(it->path(), to, both | fs::copy_options::create_hard_links, link_ec);
        if (link_ec) {
            fs::remove_all(to, link_ec);
            fs::copy(it->path(), to, both, link_ec);
        }
        if (link_ec) {
            throw Error("cannot keep " + it->path().string() + " in the new " + target.string() +
                        ": " + link_ec.message());
        }
    }
    if (ec) throw Error("cannot read " + target.string() + ": " + ec.message());
}

/// Step 3 where the exchange is refused: the documented rename pair.
void rename_pair(const fs::path& target, const fs::path& staging) {
    const fs::path backup = backup_of(target);
    std::error_code ec;
    fs::remove_all(backup, ec);
    detail::rename_path(target, backup);
    try {
        detail::rename_path(staging, target);
    } catch (const Error&) {
        recover_directory(target);  // the old folder back in place
        throw;
    }
    detail::sync_path(detail::parent_folder(target));
    fs::remove_all(backup, ec);
}

}  // namespace

bool recover_directory(const fs::path& target) noexcept {
    std::error_code ec;
    bool restored = false;
    const fs::path backup = backup_of(target);
    if (fs::is_directory(backup, ec)) {
        if (!fs::exists(fs::symlink_status(target, ec))) {
            fs::rename(backup, target, ec);
            restored = !ec;
        } else {
            fs::remove_all(backup, ec);
        }
    }
    const std::string name = target.filename().string();
    for (fs::directory_iterator it(detail::parent_folder(target), ec), end; !ec && it != end;
         it.increment(ec)) {
        std::error_code remove_ec;
        if (process_gone(detail::temp_owner(it->path().filename().string(), name))) {
            fs::remove_all(it->path(), remove_ec);
        }
    }
    return restored;
}

AtomicDirectory::AtomicDirectory(fs::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
    std::error_code ec;
    if (fs::is_symlink(target_, ec)) target_ = fs::canonical(target_, ec);  // swap its folder
    if (fs::exists(target_, ec) && !fs::is_directory(target_, ec)) {
        throw UsageError("cannot write into " + target_.string() + ": it is a file, not a folder");
    }
    const fs::path parent = detail::parent_folder(target_);
    fs::create_directories(parent, ec);
    recover_directory(target_);
    staging_ = parent / detail::temp_name(target_.filename().string());
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
    carry_over(target_, staging_, files_);
    detail::sync_tree(staging_);
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(target_, ec))) {
        detail::rename_path(staging_, target_);
    } else if (const int error = detail::exchange_paths(staging_, target_); error == 0) {
        // The old folder is now under the staging name; the destructor removes it.
    } else if (error == EINVAL || error == ENOSYS || error == EOPNOTSUPP) {
        rename_pair(target_, staging_);
    } else {
        throw Error("cannot move the products into " + target_.string() + ": " +
                    std::strerror(error));
    }
    committed_ = true;
    detail::sync_path(detail::parent_folder(target_));
    fs::remove_all(staging_, ec);
}

}  // namespace dtm::io
