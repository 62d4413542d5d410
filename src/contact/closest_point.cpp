// Closest points of a batch of candidate pairs (docs/theory/contact.md, eq. C-1): one loop over the pairs of the
// batch, the four-triangle fan of kernels.hpp inlined without branches, so that the compiler vectorises it
// (checked with -fopt-info-vec: "loop vectorized"; the compile options are in src/CMakeLists.txt).
#include "crumple/contact/kernels.hpp"

namespace crumple::contact {

// Compiled three times, for AVX-512, AVX2 and generic x86-64, and chosen once at load time for the CPU that runs
// it (GCC function multi-versioning): the binary stays portable and the loop runs 8, 4 or 2 pairs at a time.
[[gnu::target_clones("avx512f", "avx2", "default")]] void closest_points(PairBatch& b, int count) {
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const Vec3 x0{b.corner[0][0][i], b.corner[0][1][i], b.corner[0][2][i]};
    const Vec3 x1{b.corner[1][0][i], b.corner[1][1][i], b.corner[1][2][i]};
    const Vec3 x2{b.corner[2][0][i], b.corner[2][1][i], b.corner[2][2][i]};
    const Vec3 x3{b.corner[3][0][i], b.corner[3][1][i], b.corner[3][2][i]};
    const FanPoint f = closest_on_fan({b.node[0][i], b.node[1][i], b.node[2][i]}, x0, x1, x2, x3);
    b.distance[i] = std::sqrt(f.distance2);
    b.weight[0][i] = f.w0, b.weight[1][i] = f.w1, b.weight[2][i] = f.w2, b.weight[3][i] = f.w3;
    b.point[0][i] = f.w0 * x0.x + f.w1 * x1.x + f.w2 * x2.x + f.w3 * x3.x;
    b.point[1][i] = f.w0 * x0.y + f.w1 * x1.y + f.w2 * x2.y + f.w3 * x3.y;
    b.point[2][i] = f.w0 * x0.z + f.w1 * x1.z + f.w2 * x2.z + f.w3 * x3.z;
  }
}

}  // namespace crumple::contact
