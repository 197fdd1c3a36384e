// SPDX-License-Identifier: Apache-2.0
#include "common/ranks.h"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <thread>

#include "common/exit_code.h"

namespace hmcr {
namespace {

Ranks g_world;

// Open MPI's mpirun, MPICH's Hydra and Slurm's srun (PMI or PMIx) each set one of these.
bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"}) {
        if (std::getenv(name)) return true;
    }
    return false;
}

void check(int status, const char* what) {
    if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

int count_of(std::size_t n) {
    if (n > std::size_t(std::numeric_limits<int>::max())) {
        throw std::runtime_error("MPI: a message of more than 2 GB");
    }
    return int(n);
}

}  // namespace

const Ranks& Ranks::world() { return g_world; }

const Ranks& Ranks::single() {
    static const Ranks alone;
    return alone;
}

void Ranks::sum(std::span<std::int64_t> values) const {
    if (!m_mpi || values.empty()) return;
    check(MPI_Allreduce(MPI_IN_PLACE, values.data(), count_of(values.size()), MPI_INT64_T, MPI_SUM,
                        MPI_COMM_WORLD),
          "a sum");
}

void Ranks::sum(std::span<std::uint64_t> values) const {
    if (!m_mpi || values.empty()) return;
    check(MPI_Allreduce(MPI_IN_PLACE, values.data(), count_of(values.size()), MPI_UINT64_T, MPI_SUM,
                        MPI_COMM_WORLD),
          "a sum");
}

std::vector<std::string> Ranks::gather_all(const std::string& bytes) const {
    if (!m_mpi) return {bytes};
    const int mine = count_of(bytes.size());
    const auto n = static_cast<std::size_t>(m_size);
    std::vector<int> counts(n), offsets(n);
    check(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "a gather");
    std::size_t total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        offsets[r] = count_of(total);
        total += std::size_t(counts[r]);
    }
    std::string all(total, '\0');
    check(MPI_Allgatherv(bytes.data(), mine, MPI_BYTE, all.data(), counts.data(), offsets.data(),
                         MPI_BYTE, MPI_COMM_WORLD),
          "a gather");
    std::vector<std::string> out;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        out.push_back(all.substr(std::size_t(offsets[r]), std::size_t(counts[r])));
    }
    return out;
}

void Ranks::agree(const std::exception_ptr& error) const {
    if (!m_mpi) {
        if (error) std::rethrow_exception(error);
        return;
    }
    std::string mine;
    if (error) {
        const Failure f = failure_of(error);
        mine = std::to_string(f.exit_code) + " " + f.message;
    }
    for (const std::string& s : gather_all(mine)) {
        if (s.empty()) continue;
        if (error) std::rethrow_exception(error);
        const std::size_t space = s.find(' ');
        throw OtherRankFailed(s.substr(space + 1), std::stoi(s.substr(0, space)));
    }
}

void Ranks::send(int to, int tag, const std::string& bytes) const {
    check(MPI_Send(bytes.data(), count_of(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD),
          "a send");
}

std::string Ranks::receive(int from, int tag) const {
    MPI_Status status;
    check(MPI_Probe(from, tag, MPI_COMM_WORLD, &status), "a probe");
    int n = 0;
    MPI_Get_count(&status, MPI_BYTE, &n);
    std::string bytes(std::size_t(n), '\0');
    check(MPI_Recv(bytes.data(), n, MPI_BYTE, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "a receive");
    return bytes;
}

std::pair<int, std::string> Ranks::receive_any(int tag, const std::function<void()>& idle) const {
    for (;;) {
        int ready = 0;
        MPI_Status status;
        check(MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &ready, &status), "a probe");
        if (ready) return {status.MPI_SOURCE, receive(status.MPI_SOURCE, tag)};
        if (idle) idle();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

MpiSession::MpiSession(int& argc, char**& argv) {
    if (!launched_by_mpi()) return;
    // Only the main thread calls MPI (TBB's workers never do).
    int provided = 0;
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "starting");
    m_started = true;
    g_world.m_mpi = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &g_world.m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_world.m_size);
}

MpiSession::~MpiSession() {
    if (m_started) MPI_Finalize();
}

}  // namespace hmcr
