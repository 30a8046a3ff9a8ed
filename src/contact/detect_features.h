// The features pass of contact detection: what passes between the nodes. After the node pass
// (detect_node_triangle.h) has held every node out of the faces and shapes it meets, this pass
// finds a rigid shape poking into a face between its nodes (face_shape.h) and two bodies' sharp
// edges crossing (edge_edge.h), between x^n and x* of the sub-step, over the same candidates:
// the bodies near each shape, the moving bodies' triangle trees the last search made
// (contact_candidates.h) and the pairs of edges made after it (edge_candidates.h). Its records
// join the list after the node records of their body_a (their node is kFeatureNode), ordered by
// kind, shape and nodes, and warm-start from the last list's records of the same feature (a
// shape's also by place: detect_features.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/profile.h"
#include "common/thread_pool.h"
#include "contact/contact_body.h"
#include "contact/contact_candidates.h"
#include "contact/contact_record.h"
#include "contact/edge_candidates.h"

namespace lfem {

// Points sorted along x, for the points within a reach of a given one in O(log n + k) (the
// records of one shape under one body, a few dozen, but a large sphere under a fine mesh meets
// hundreds).
class PlaceIndex {
public:
    void clear() { by_x_.clear(); }
    void add(const double* p, uint32_t id) { by_x_.push_back({p[0], id, p}); }
    void sort() {
        std::sort(by_x_.begin(), by_x_.end(), [](const Entry& a, const Entry& b) { return a.x != b.x ? a.x < b.x : a.id < b.id; });
    }
    // visit(id, squared distance) for every point within `reach` of p.
    template <class Visit>
    void near(const double* p, double reach, const Visit& visit) const {
        auto it = std::lower_bound(by_x_.begin(), by_x_.end(), p[0] - reach, [](const Entry& e, double x) { return e.x < x; });
        for (; it != by_x_.end() && it->x <= p[0] + reach; ++it) {
            const double dx = it->p[0] - p[0], dy = it->p[1] - p[1], dz = it->p[2] - p[2];
            const double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 <= reach * reach) visit(it->id, d2);
        }
    }

private:
    struct Entry {
        double x;
        uint32_t id;
        const double* p;
    };
    std::vector<Entry> by_x_;
};

// Scratch kept between sub-steps for its capacity.
struct FeatureScratch {
    std::vector<ContactRecord> found, merged;
    std::vector<double> start_gaps;               // per face-shape record found: its gap at x^n
    PlaceIndex previous_places;                   // of the shape's last records
    std::vector<const ContactRecord*> previous;  // the last list's feature records, in order
    std::vector<uint32_t> near;                   // bodies near a shape
    std::vector<uint32_t> triangles;              // of one body near a shape
    std::vector<Aabb> regions;                    // where a shape's points under faces may be
    std::vector<uint32_t> match, shares;          // warm start by place (detect_features.cpp)
    EdgeCandidates edges;                         // sharp edges that may cross, watched folds
    std::vector<std::vector<ContactRecord>> edge_found;  // per block of the edge pass
};

// The order of feature records of the same pair of bodies: kind, body_b's shape, body_a's
// nodes, which of the shape's points under the face.
bool feature_less(const ContactRecord& x, const ContactRecord& y);

// Adds the feature records to `list` (the node pass's, with its runs of one pair of bodies
// `runs`, both updated). Leaves both untouched when no feature is found.
void detect_features(const std::vector<ContactBody>& bodies, const ContactCandidates& c,
                     const std::vector<ContactRecord>& previous, FeatureScratch& s, std::vector<ContactRecord>& list,
                     std::vector<RecordRun>& runs, Profile& profile, ThreadPool* pool);

}  // namespace lfem
