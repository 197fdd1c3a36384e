// SPDX-License-Identifier: Apache-2.0
// The processes of an MPI run (docs/cluster.md). hmcr initialises MPI only when a launcher
// started it (mpirun, mpiexec or srun set their variables); otherwise it is rank 0 of 1 and
// never touches MPI, so a plain run costs nothing and needs no daemon.
//
// Every collective here must be reached by every rank: code that may throw between two of them
// runs inside together(), which catches, reaches agree() on every rank, and rethrows there (see
// radiosity/solver.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace hmcr {

class Ranks {
public:
    // The run's ranks: MPI_COMM_WORLD when MpiSession started MPI, else one rank.
    static const Ranks& world();
    // This process alone (a study's cell, whose rank shares it with no other).
    static const Ranks& single();

    int rank() const { return m_rank; }
    int size() const { return m_size; }
    bool root() const { return m_rank == 0; }

    // Element-wise sums over all ranks, in place (integers: exact, so the same on every rank).
    void sum(std::span<std::int64_t> values) const;
    void sum(std::span<std::uint64_t> values) const;
    // Every rank's bytes, by rank.
    std::vector<std::string> gather_all(const std::string& bytes) const;
    // A collective every rank reaches whether or not its own part failed (`error`): if any
    // did, every rank throws, the failed ones their own exception, the others OtherRankFailed
    // with the lowest failed rank's exit code and message.
    void agree(const std::exception_ptr& error) const;

    // Point to point, for the study's hand-out of cells (tags keep the kinds apart).
    void send(int to, int tag, const std::string& bytes) const;
    // Waits for a message of `tag` from any rank, calling `idle` every few milliseconds (to
    // notice signals); returns (sender, bytes).
    std::pair<int, std::string> receive_any(int tag, const std::function<void()>& idle) const;
    std::string receive(int from, int tag) const;

private:
    friend class MpiSession;
    int m_rank = 0, m_size = 1;
    bool m_mpi = false;
};

// Starts MPI for the process's lifetime when a launcher started it (main holds one).
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

private:
    bool m_started = false;
};

// A collective failed on another rank, which reports it: this rank ends with its exit code
// and says nothing (one message per run, not one per rank).
class OtherRankFailed : public std::runtime_error {
public:
    OtherRankFailed(const std::string& message, int exit_code)
        : std::runtime_error(message), m_exit_code(exit_code) {}
    int exit_code() const { return m_exit_code; }

private:
    int m_exit_code;
};

// Runs `part` on every rank, then agree()s on whether it failed anywhere.
template <class F>
void together(const Ranks& ranks, F&& part) {
    std::exception_ptr error;
    try {
        part();
    } catch (...) {
        error = std::current_exception();
    }
    ranks.agree(error);
}

}  // namespace hmcr
