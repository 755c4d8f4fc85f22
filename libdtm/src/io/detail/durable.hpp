// SPDX-License-Identifier: MIT
// Durability helpers of the atomic outputs (POSIX): flush a file or a folder to the disk, exchange
// two paths in one step, name hidden temporaries.
#pragma once

#include <filesystem>
#include <string>

namespace dtm::io::detail {

/// The folder holding @p path ("." for a bare file name).
std::filesystem::path parent_folder(const std::filesystem::path& path);

/// rename(2). @throws Error "cannot move FROM to TO: reason".
void rename_path(const std::filesystem::path& from, const std::filesystem::path& to);

/// ".<name>.tmp-<pid>-<n>", n counting up in this process.
std::string temp_name(const std::string& name);

/// The pid in a temporary's name ".<name>.tmp-<pid>-<n>", 0 when @p file is not one for @p name.
long temp_owner(const std::string& file, const std::string& name);

/// fsync(2) of a file, or of a folder's entries; errors ignored where the file system cannot sync
/// a folder (EINVAL). @throws Error when the data cannot be flushed (EIO, ENOSPC, EDQUOT).
void sync_path(const std::filesystem::path& path);

/// Every regular file and folder under @p folder, then @p folder itself.
void sync_tree(const std::filesystem::path& folder);

/// renameat2(RENAME_EXCHANGE): @p a and @p b swap places in one atomic step. Returns 0 or the
/// errno (EINVAL, ENOSYS, EOPNOTSUPP when the file system or the kernel cannot exchange).
int exchange_paths(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace dtm::io::detail
