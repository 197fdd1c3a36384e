#include "viz/solution_file.h"

namespace hmcr {

VtpMetadata vtp_metadata(const Solution& solution, double time_value) {
    const SolveStats& st = solution.stats;
    const bool uniform = solution.options.uniform_max_area > 0;
    return {uniform ? "uniform" : solution.options.oracle,
            uniform ? 0 : st.epsilon,
            uniform ? 0 : std::uint64_t(solution.options.lines),
            st.rays,
            solution.options.seed,
            st.leaves,
            st.iterations.size(),
            time_value};
}

ShadedMesh shade(const Solution& solution, const PatchMesh& mesh, double crease_degrees) {
    return build_shaded_mesh(*solution.hierarchy, mesh, crease_degrees);
}

void write_solution(const std::filesystem::path& vtp, const ShadedMesh& shaded,
                    const Solution& solution, double time_value) {
    write_vtp(vtp, shaded, vtp_metadata(solution, time_value));
}

ShadedMesh write_solution(const std::filesystem::path& vtp, const Solution& solution,
                          const PatchMesh& mesh, double crease_degrees, double time_value) {
    ShadedMesh shaded = shade(solution, mesh, crease_degrees);
    write_solution(vtp, shaded, solution, time_value);
    return shaded;
}

}  // namespace hmcr
