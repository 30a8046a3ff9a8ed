// The tree of a body's triangles (src/contact/triangle_bvh.h) finds exactly the triangles whose
// box overlaps a query box: compared with testing every triangle, on a random soup of triangles
// of very different sizes, after it is built and again after the nodes moved and it was refitted
// (contact's candidates rely on it missing nothing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "contact/triangle_bvh.h"

namespace lfem {
namespace {

Aabb box_of(const std::vector<double>& x, const std::vector<uint32_t>& tri, uint32_t t) {
    Aabb b = empty_box();
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
            b.lo[k] = std::min(b.lo[k], x[3 * tri[3 * t + v] + k]);
            b.hi[k] = std::max(b.hi[k], x[3 * tri[3 * t + v] + k]);
        }
    return b;
}

// Every query's answer, sorted, against the brute-force one.
void expect_exact(const TriangleBvh& tree, const std::vector<double>& x, const std::vector<uint32_t>& tri,
                  std::mt19937& rng) {
    std::uniform_real_distribution<double> where(-1.0, 1.0), size(0.0, 0.3);
    uint64_t found_total = 0;
    for (int q = 0; q < 500; ++q) {
        Aabb box;
        for (int k = 0; k < 3; ++k) {
            const double c = where(rng), r = size(rng);
            box.lo[k] = c - r, box.hi[k] = c + r;
        }
        std::vector<uint32_t> found, expected;
        tree.query(box, x.data(), tri.data(), 0.0, [&](uint32_t t) { found.push_back(t); });
        for (uint32_t t = 0; t < tri.size() / 3; ++t)
            if (overlaps(box_of(x, tri, t), box)) expected.push_back(t);
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, expected) << "query " << q;
        found_total += found.size();
    }
    EXPECT_GT(found_total, 500u);  // the queries do meet triangles
}

TEST(TriangleBvh, FindsExactlyTheOverlappingTrianglesBeforeAndAfterARefit) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> where(-1.0, 1.0), jitter(-0.01, 0.01);
    std::uniform_int_distribution<int> scale(0, 2);
    const uint32_t triangles = 3000;
    std::vector<double> x;
    std::vector<uint32_t> tri;
    for (uint32_t t = 0; t < triangles; ++t) {
        // Triangles from 1e-3 to 1 across: a terrain's and a cube's side by side.
        const double s = std::pow(10.0, -scale(rng));
        double c[3];
        for (double& ck : c) ck = where(rng);
        for (int v = 0; v < 3; ++v) {
            for (int k = 0; k < 3; ++k) x.push_back(c[k] + s * where(rng));
            tri.push_back(uint32_t(x.size() / 3 - 1));
        }
    }
    TriangleBvh tree;
    tree.build(x.data(), tri.data(), triangles);
    expect_exact(tree, x, tri, rng);
    for (double& xi : x) xi += jitter(rng);  // the nodes move; the tree keeps its shape
    tree.refit(x.data(), tri.data());
    expect_exact(tree, x, tri, rng);
}

TEST(TriangleBvh, EmptyAndSingleTriangleTrees) {
    TriangleBvh empty;
    empty.build(nullptr, nullptr, 0);
    EXPECT_TRUE(empty.empty());
    int visits = 0;
    empty.query(Aabb{{-1, -1, -1}, {1, 1, 1}}, nullptr, nullptr, 0.0, [&](uint32_t) { ++visits; });
    EXPECT_EQ(visits, 0);
    const std::vector<double> x = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::vector<uint32_t> tri = {0, 1, 2};
    TriangleBvh one;
    one.build(x.data(), tri.data(), 1);
    one.query(Aabb{{0.9, 0.9, -1}, {2, 2, 1}}, x.data(), tri.data(), 0.0, [&](uint32_t) { ++visits; });  // in its box
    EXPECT_EQ(visits, 1);
    one.query(Aabb{{1.1, 0, 0}, {2, 1, 1}}, x.data(), tri.data(), 0.0, [&](uint32_t) { ++visits; });
    EXPECT_EQ(visits, 1);
}

}  // namespace
}  // namespace lfem
