#include "kernels/cpu/jacobi_repair.hpp"

namespace tetsmooth {

std::int64_t repair_jacobi_conflicts(const MeshView& view, std::size_t num_tets, index_t num_nodes,
                                     AosCoords<double> before, AosCoords<double> after, std::uint8_t* moved,
                                     std::uint8_t* revert, const double* old_min, int threads, int max_passes) {
  std::int64_t reverted_total = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::int64_t objecting = 0;
#pragma omp parallel for num_threads(threads) if (threads > 1) schedule(static) reduction(+ : objecting)
    for (std::size_t t = 0; t < num_tets; ++t) {
      const index_t* tv = view.tets + 4 * t;
      if (!tet_rejects_movers(tv, before, after, moved, old_min)) continue;
      ++objecting;
      for (int k = 0; k < 4; ++k)
        if (moved[tv[k]]) {
#pragma omp atomic write
          revert[tv[k]] = 1;
        }
    }
    if (objecting == 0) break;
    // The last pass found conflicts it may not have cleared: undo the sweep.
    const bool undo_all = repair_undoes_sweep(pass, max_passes);
    std::int64_t reverted = 0;
#pragma omp parallel for num_threads(threads) if (threads > 1) schedule(static) reduction(+ : reverted)
    for (index_t i = 0; i < num_nodes; ++i) reverted += revert_if_flagged(i, before, after, moved, revert, undo_all);
    reverted_total += reverted;
  }
  return reverted_total;
}

}  // namespace tetsmooth
