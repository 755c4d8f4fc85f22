// SPDX-License-Identifier: MIT
//
// MPI backend of dist::Comm. Payloads of any size: variable exchanges go as point-to-point
// messages of at most 1 GiB each on a private duplicate of MPI_COMM_WORLD, posted for every peer
// and completed together, and are placed by source rank, so the result never depends on arrival
// order. Reductions use MPI_INT64_T only.
#include "dtm/dist/mpi_comm.hpp"

#include <cstdlib>
#include <initializer_list>
#include <string>

#include "dtm/core/error.hpp"

#if DTM_WITH_MPI
// The C API only: no C++ bindings (removed from the MPI standard).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <span>
#endif

namespace dtm::dist {

namespace {

/// The first of the launcher's variables @p names that is set, as a number; 0 when none is.
int launcher_count(std::initializer_list<const char*> names) noexcept {
    for (const char* name : names) {
        if (const char* value = std::getenv(name)) return std::atoi(value);
    }
    return 0;
}

}  // namespace

int launched_ranks() noexcept {
    return launcher_count({"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"});
}

int launched_local_ranks() noexcept {
    return launcher_count({"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"});
}

#if DTM_WITH_MPI

bool mpi_built() noexcept { return true; }

namespace {

constexpr std::size_t chunk_bytes = std::size_t{1} << 30;

void check(int code, const char* what) {
    if (code != MPI_SUCCESS) {
        char text[MPI_MAX_ERROR_STRING];
        int length = 0;
        MPI_Error_string(code, text, &length);
        throw Error(std::string("MPI ") + what + " failed: " + std::string(text, length));
    }
}

MPI_Op to_op(Reduce op) {
    return op == Reduce::min ? MPI_MIN : (op == Reduce::max ? MPI_MAX : MPI_SUM);
}

/// SharedFile on MPI-IO: MPI_File_open on the job's communicator, truncated, independent
/// writes at explicit offsets; an error is kept until the collective close.
class MpiSharedFile final : public SharedFile {
public:
    MpiSharedFile(Comm& comm, MPI_Comm mpi, std::string path)
        : comm_(comm), path_(std::move(path)) {
        const int code = MPI_File_open(mpi, path_.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY,
                                       MPI_INFO_NULL, &file_);
        if (code != MPI_SUCCESS) {
            remember(code, "cannot create the file");
            file_ = MPI_FILE_NULL;
        }
        // Collective on every rank that opened it: the job fails together below otherwise.
        if (comm_.allreduce(file_ == MPI_FILE_NULL ? 1 : 0, Reduce::max) != 0) {
            if (file_ != MPI_FILE_NULL) MPI_File_close(&file_);
            throw_first_error(comm_, error_);
        }
        MPI_File_set_errhandler(file_, MPI_ERRORS_RETURN);
        const int truncated = MPI_File_set_size(file_, 0);
        if (truncated != MPI_SUCCESS) remember(truncated, "cannot truncate the file");
    }
    ~MpiSharedFile() override {
        if (file_ != MPI_FILE_NULL) MPI_File_close(&file_);
    }

    void write_at(std::uint64_t offset, std::span<const std::byte> bytes) override {
        if (!error_.empty()) return;
        for (std::size_t at = 0; at < bytes.size(); at += chunk_bytes) {
            const int n = static_cast<int>(std::min(chunk_bytes, bytes.size() - at));
            const int code = MPI_File_write_at(file_, static_cast<MPI_Offset>(offset + at),
                                               bytes.data() + at, n, MPI_BYTE, MPI_STATUS_IGNORE);
            if (code != MPI_SUCCESS) {
                remember(code, "write failed");
                return;
            }
        }
    }

    void close() override {
        if (file_ != MPI_FILE_NULL) {
            if (error_.empty()) {
                const int synced = MPI_File_sync(file_);
                if (synced != MPI_SUCCESS) remember(synced, "write failed");
            }
            const int closed = MPI_File_close(&file_);
            if (closed != MPI_SUCCESS) remember(closed, "write failed");
            file_ = MPI_FILE_NULL;
        }
        if (comm_.allreduce(error_.empty() ? 0 : 1, Reduce::max) != 0)
            throw_first_error(comm_, error_);
    }

private:
    void remember(int code, const char* what) {
        if (!error_.empty()) return;
        char text[MPI_MAX_ERROR_STRING];
        int length = 0;
        MPI_Error_string(code, text, &length);
        error_ = "cannot write " + path_ + ": " + what + " (" +
                 std::string(text, static_cast<std::size_t>(length)) + ")";
    }

    Comm& comm_;
    std::string path_;
    MPI_File file_ = MPI_FILE_NULL;
    std::string error_;
};

class MpiComm final : public Comm {
public:
    explicit MpiComm(MPI_Comm world) {
        check(MPI_Comm_dup(world, &comm_), "Comm_dup");
        check(MPI_Comm_rank(comm_, &rank_), "Comm_rank");
        check(MPI_Comm_size(comm_, &size_), "Comm_size");
    }
    ~MpiComm() override { MPI_Comm_free(&comm_); }

    [[nodiscard]] int rank() const noexcept override { return rank_; }
    [[nodiscard]] int size() const noexcept override { return size_; }
    std::unique_ptr<SharedFile> open_shared(const std::string& path) override {
        return std::make_unique<MpiSharedFile>(*this, comm_, path);
    }

protected:
    std::vector<Bytes> do_alltoallv(std::vector<Bytes> out) override {
        const auto p = static_cast<std::size_t>(size_);
        std::vector<std::int64_t> send_sizes(p), recv_sizes(p);
        for (std::size_t r = 0; r < p; ++r)
            send_sizes[r] = static_cast<std::int64_t>(out[r].size());
        check(MPI_Alltoall(send_sizes.data(), 1, MPI_INT64_T, recv_sizes.data(), 1, MPI_INT64_T,
                           comm_),
              "Alltoall");
        std::vector<Bytes> in(p);
        for (std::size_t s = 0; s < p; ++s) in[s].resize(static_cast<std::size_t>(recv_sizes[s]));
        in[static_cast<std::size_t>(rank_)] = std::move(out[static_cast<std::size_t>(rank_)]);
        std::vector<MPI_Request> requests;
        for (std::size_t s = 0; s < p; ++s) {
            if (static_cast<int>(s) != rank_)
                post(in[s].data(), in[s].size(), static_cast<int>(s), true, requests);
        }
        for (std::size_t r = 0; r < p; ++r) {
            if (static_cast<int>(r) != rank_)
                post(out[r].data(), out[r].size(), static_cast<int>(r), false, requests);
        }
        complete(requests);
        return in;
    }

    std::vector<Bytes> do_allgatherv(Bytes mine) override {
        std::vector<Bytes> out(static_cast<std::size_t>(size_));
        for (auto& o : out) o = mine;
        return do_alltoallv(std::move(out));
    }

    void do_allreduce(std::span<std::int64_t> values, Reduce op) override {
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()),
                            MPI_INT64_T, to_op(op), comm_),
              "Allreduce");
    }

    std::int64_t do_exscan_sum(std::int64_t value) override {
        std::int64_t result = 0;
        check(MPI_Exscan(&value, &result, 1, MPI_INT64_T, MPI_SUM, comm_), "Exscan");
        return rank_ == 0 ? 0 : result;
    }

    void do_bcast(Bytes& data, int root) override {
        std::int64_t size = static_cast<std::int64_t>(data.size());
        check(MPI_Bcast(&size, 1, MPI_INT64_T, root, comm_), "Bcast");
        data.resize(static_cast<std::size_t>(size));
        for (std::size_t at = 0; at < data.size(); at += chunk_bytes) {
            const std::size_t n = std::min(chunk_bytes, data.size() - at);
            check(MPI_Bcast(data.data() + at, static_cast<int>(n), MPI_BYTE, root, comm_), "Bcast");
        }
    }

    void do_barrier() override { check(MPI_Barrier(comm_), "Barrier"); }

private:
    /// Posts the receives (or sends) of one payload in chunks; the tag is the chunk number.
    void post(std::byte* data,
              std::size_t size,
              int peer,
              bool receive,
              std::vector<MPI_Request>& requests) {
        int tag = 0;
        for (std::size_t at = 0; at < size; at += chunk_bytes, ++tag) {
            const int n = static_cast<int>(std::min(chunk_bytes, size - at));
            requests.emplace_back();
            if (receive) {
                check(MPI_Irecv(data + at, n, MPI_BYTE, peer, tag, comm_, &requests.back()),
                      "Irecv");
            } else {
                check(MPI_Isend(data + at, n, MPI_BYTE, peer, tag, comm_, &requests.back()),
                      "Isend");
            }
        }
    }

    void complete(std::vector<MPI_Request>& requests) {
        if (requests.empty()) return;
        check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
              "Waitall");
    }

    MPI_Comm comm_ = MPI_COMM_NULL;
    int rank_ = 0;
    int size_ = 1;
};

}  // namespace

struct MpiSession::Impl {
    std::unique_ptr<MpiComm> world;
};

MpiSession::MpiSession(int& argc, char**& argv) : impl_(std::make_unique<Impl>()) {
    int provided = 0;
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "Init_thread");
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    impl_->world = std::make_unique<MpiComm>(MPI_COMM_WORLD);
}

MpiSession::~MpiSession() {
    impl_->world.reset();
    MPI_Finalize();
}

Comm& MpiSession::world() noexcept { return *impl_->world; }

void MpiSession::abort(int code) noexcept {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);
}

#else

bool mpi_built() noexcept { return false; }

struct MpiSession::Impl {};

MpiSession::MpiSession(int&, char**&) {
    throw Error("this dtm was built without MPI (configure with MPI installed, DTM_WITH_MPI=ON)");
}
MpiSession::~MpiSession() = default;
Comm& MpiSession::world() noexcept { std::abort(); }
void MpiSession::abort(int code) noexcept { std::_Exit(code); }

#endif

}  // namespace dtm::dist
