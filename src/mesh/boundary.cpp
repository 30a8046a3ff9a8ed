// Boundary triangles: every tet face goes into one flat array keyed by its sorted node triple;
// a bucket sort brings the copies of a face together, faces seen once are the boundary. Flat
// records (rather than a node-based hash map) keep memory compact and the run time immune to
// hostile index patterns; the output order does not depend on the sort (see the end).
#include "mesh/boundary.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/error.h"
#include "common/quadratic_tet_nodes.h"

namespace lfem {
namespace {

// The faces of a positively oriented tet (0,1,2,3), each ordered so that (b-a)x(c-a) points
// out of the tet.
constexpr int kOutwardFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

struct FaceRecord {
    uint32_t key[3];  // node indices, ascending
    uint32_t tet;
    uint8_t local;   // which of kOutwardFaces
    uint8_t parity;  // 1 when sorting the outward triple took an odd permutation
};

bool same_key(const FaceRecord& a, const FaceRecord& b) {
    return a.key[0] == b.key[0] && a.key[1] == b.key[1] && a.key[2] == b.key[2];
}

std::string triangle_name(const FaceRecord& f) {
    return "triangle (" + std::to_string(f.key[0]) + ", " + std::to_string(f.key[1]) + ", " +
           std::to_string(f.key[2]) + ")";
}

bool face_less(const FaceRecord& a, const FaceRecord& b) {
    if (a.key[0] != b.key[0]) return a.key[0] < b.key[0];
    if (a.key[1] != b.key[1]) return a.key[1] < b.key[1];
    if (a.key[2] != b.key[2]) return a.key[2] < b.key[2];
    if (a.tet != b.tet) return a.tet < b.tet;
    return a.local < b.local;
}

// Face `local` of tet t (stride node indices per tet, the corners first) as a record: its
// sorted corner triple and the parity of the sort.
FaceRecord make_face(const uint32_t* tets, uint32_t stride, uint32_t t, int local) {
    FaceRecord r;
    uint32_t* k = r.key;
    for (int i = 0; i < 3; ++i) k[i] = tets[std::size_t(stride) * t + kOutwardFaces[local][i]];
    // Three compare-and-swaps sort the triple; each swap flips the parity, which remembers the
    // orientation the sorted key forgets.
    uint8_t parity = 0;
    const auto order = [&](int i, int j) {
        if (k[i] > k[j]) {
            std::swap(k[i], k[j]);
            parity ^= 1;
        }
    };
    order(0, 1);
    order(1, 2);
    order(0, 1);
    r.tet = t;
    r.local = uint8_t(local);
    r.parity = parity;
    return r;
}

// Every tet face, sorted by face_less, so that the copies of a face are neighbours. Usually in
// linear time: the faces are placed straight into buckets by their lowest node (a counting
// sort, with no second array of records: this is the peak of a body's memory while its mesh
// is added), and only the few faces around one node are then sorted together. Node indices
// far beyond the face count (sparse, or hostile) would make the buckets array absurd, so
// those fall back to one comparison sort.
std::vector<FaceRecord> grouped_faces(const uint32_t* tets, uint32_t stride, uint32_t tet_count) {
    if (tet_count == 0) return {};  // (also keeps GCC 12 at -O2 -g from a false -Wstringop-overflow)
    const std::size_t face_count = 4 * std::size_t(tet_count);
    uint32_t lowest_max = 0;
    for (uint32_t t = 0; t < tet_count; ++t)
        for (int f = 0; f < 4; ++f) lowest_max = std::max(lowest_max, make_face(tets, stride, t, f).key[0]);
    std::vector<FaceRecord> faces(face_count);
    if (lowest_max > face_count) {
        for (uint32_t t = 0; t < tet_count; ++t)
            for (int f = 0; f < 4; ++f) faces[4 * std::size_t(t) + f] = make_face(tets, stride, t, f);
        std::sort(faces.begin(), faces.end(), face_less);
        return faces;
    }
    std::vector<std::size_t> bucket_start(std::size_t(lowest_max) + 2, 0);
    for (uint32_t t = 0; t < tet_count; ++t)
        for (int f = 0; f < 4; ++f) ++bucket_start[std::size_t(make_face(tets, stride, t, f).key[0]) + 1];
    for (std::size_t b = 1; b < bucket_start.size(); ++b) bucket_start[b] += bucket_start[b - 1];
    std::vector<std::size_t> next(bucket_start.begin(), bucket_start.end() - 1);
    for (uint32_t t = 0; t < tet_count; ++t)
        for (int f = 0; f < 4; ++f) {
            const FaceRecord r = make_face(tets, stride, t, f);
            faces[next[r.key[0]]++] = r;
        }
    for (std::size_t b = 0; b + 1 < bucket_start.size(); ++b)
        std::sort(faces.begin() + bucket_start[b], faces.begin() + bucket_start[b + 1], face_less);
    return faces;
}

// Flags the faces seen once, by their place (4 * tet + face) in the input.
std::vector<unsigned char> boundary_flags(const uint32_t* tets, uint32_t stride, uint32_t tet_count,
                                          std::size_t& boundary_count) {
    const std::vector<FaceRecord> faces = grouped_faces(tets, stride, tet_count);
    std::vector<unsigned char> on_boundary(faces.size(), 0);
    boundary_count = 0;
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t end = i + 1;
        while (end < faces.size() && same_key(faces[i], faces[end])) ++end;
        if (end - i > 2)
            throw Error(Status::invalid_mesh,
                        triangle_name(faces[i]) + " is shared by more than two tets (tets " +
                            std::to_string(faces[i].tet) + ", " + std::to_string(faces[i + 1].tet) +
                            " and " + std::to_string(faces[i + 2].tet) + ")");
        if (end - i == 2 && faces[i].parity == faces[i + 1].parity)
            // Two positively oriented tets on either side of a triangle see it with opposite
            // orientations; the same orientation means they lie on the same side: they
            // overlap, or one tet is listed twice.
            throw Error(Status::invalid_mesh,
                        "tets " + std::to_string(faces[i].tet) + " and " +
                            std::to_string(faces[i + 1].tet) + " lie on the same side of " +
                            triangle_name(faces[i]) + ": they overlap or are duplicates");
        if (end - i == 1) {
            on_boundary[4 * std::size_t(faces[i].tet) + faces[i].local] = 1;
            ++boundary_count;
        }
        i = end;
    }
    return on_boundary;
}

}  // namespace

std::vector<uint32_t> extract_boundary_triangles(const uint32_t* tets, uint32_t tet_count) {
    std::size_t boundary_count = 0;
    const std::vector<unsigned char> on_boundary = boundary_flags(tets, 4, tet_count, boundary_count);
    // Order of first appearance: by tet, then by face within the tet.
    std::vector<uint32_t> triangles;
    triangles.reserve(3 * boundary_count);
    for (std::size_t face = 0; face < on_boundary.size(); ++face)
        if (on_boundary[face])
            for (int i = 0; i < 3; ++i)
                triangles.push_back(tets[4 * (face / 4) + kOutwardFaces[face % 4][i]]);
    return triangles;
}

std::vector<uint32_t> extract_quadratic_boundary(const uint32_t* tets, uint32_t tet_count) {
    std::size_t boundary_count = 0;
    const std::vector<unsigned char> on_boundary =
        boundary_flags(tets, kQuadraticTetNodes, tet_count, boundary_count);
    std::vector<uint32_t> faces;
    faces.reserve(6 * boundary_count);
    for (std::size_t face = 0; face < on_boundary.size(); ++face) {
        if (!on_boundary[face]) continue;
        const uint32_t* tet = tets + kQuadraticTetNodes * (face / 4);
        const int* corner = kOutwardFaces[face % 4];
        for (int i = 0; i < 3; ++i) faces.push_back(tet[corner[i]]);
        for (int i = 0; i < 3; ++i) faces.push_back(tet[mid_edge_node(corner[i], corner[(i + 1) % 3])]);
    }
    return faces;
}

}  // namespace lfem
