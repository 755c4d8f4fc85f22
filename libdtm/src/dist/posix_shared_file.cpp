// SPDX-License-Identifier: MIT
//
// SharedFile on POSIX pwrite (posix_shared_file.hpp). A write error is kept until close(), where
// an integer reduction tells every rank, so all ranks fail together with the first message.
#include "dist/posix_shared_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "dtm/core/error.hpp"

namespace dtm::dist {
namespace {

class PosixSharedFile final : public SharedFile {
public:
    PosixSharedFile(Comm& comm, std::string path) : comm_(comm), path_(std::move(path)) {
        if (comm_.rank() == 0) {
            fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
            if (fd_ < 0) remember("cannot create the file");
        }
        if (comm_.allreduce(error_.empty() ? 0 : 1, Reduce::max) != 0) {
            throw_first_error(comm_, error_);
        }
        if (comm_.rank() != 0) {
            fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
            if (fd_ < 0) remember("cannot open the file");
        }
    }
    ~PosixSharedFile() override {
        if (fd_ >= 0) ::close(fd_);
    }

    void write_at(std::uint64_t offset, std::span<const std::byte> bytes) override {
        if (fd_ < 0 || !error_.empty()) return;
        std::size_t done = 0;
        while (done < bytes.size()) {
            const ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done,
                                       static_cast<off_t>(offset + done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                remember("write failed");
                return;
            }
            done += static_cast<std::size_t>(n);
        }
    }

    void close() override {
        if (fd_ >= 0) {
            if (error_.empty() && ::fsync(fd_) != 0) remember("write failed");
            if (::close(fd_) != 0 && error_.empty()) remember("write failed");
            fd_ = -1;
        }
        if (comm_.allreduce(error_.empty() ? 0 : 1, Reduce::max) != 0)
            throw_first_error(comm_, error_);
    }

private:
    void remember(const char* what) {
        if (error_.empty())
            error_ = "cannot write " + path_ + ": " + what + " (" + std::strerror(errno) + ")";
    }

    Comm& comm_;
    std::string path_;
    int fd_ = -1;
    std::string error_;
};

}  // namespace

std::unique_ptr<SharedFile> open_posix_shared(Comm& comm, const std::string& path) {
    return std::make_unique<PosixSharedFile>(comm, path);
}

}  // namespace dtm::dist
