// C shim of the contact query: the world's contact records as lfem_contact, in the caller's
// node numbering and a fixed order.
#include <algorithm>
#include <string>
#include <tuple>

#include "api/handles.h"

using namespace lfem;
using namespace lfem::api;

namespace {

lfem_contact_kind kind_of(const ContactRecord& c) {
    switch (c.kind) {
        case ContactKind::face_shape: return LFEM_CONTACT_FACE_SHAPE;
        case ContactKind::edge_edge: return LFEM_CONTACT_EDGE_EDGE;
        default: return c.shape != UINT32_MAX ? LFEM_CONTACT_NODE_SHAPE : LFEM_CONTACT_NODE_FACE;
    }
}

// The C record of a contact (handles, the caller's node numbers, contact point, force).
lfem_contact contact_as_c(const World& w, const ContactRecord& c) {
    lfem_contact out{};
    const Body& a = w.bodies().slot(c.body_a);
    const Body& b = w.bodies().slot(c.body_b);
    out.body_a = to_c(w.bodies().handle_of(c.body_a));
    out.body_b = to_c(w.bodies().handle_of(c.body_b));
    // A feature reports the first node of body_a's edge or face.
    out.node = a.numbering().api_node(c.feature() ? c.nodes_a[0] : c.node);
    out.shape = c.shape;
    out.kind = uint8_t(kind_of(c));
    const double wt[3] = {1.0 - c.t1 - c.t2, c.t2, c.t1};
    for (int k = 0; k < 3; ++k) {
        out.triangle[k] = c.shape != UINT32_MAX ? c.triangle[k] : b.numbering().api_node(c.triangle[k]);
        out.normal[k] = c.normal[k];
        out.force[k] = c.lambda_n * c.normal[k] + c.lambda_t[k];
        if (c.shape != UINT32_MAX)
            out.position[k] = c.point_end[k];
        else
            for (int v = 0; v < 3; ++v) out.position[k] += wt[v] * b.positions()[3 * std::size_t(c.triangle[v]) + k];
    }
    out.barycentric[0] = c.t1;
    out.barycentric[1] = c.t2;
    // body_a's side: the node alone, or the feature's nodes with their weights.
    const int a_nodes = !c.feature() ? 1 : c.side_nodes();
    for (int k = 0; k < 3; ++k) {
        out.nodes_a[k] = k < a_nodes ? a.numbering().api_node(c.feature() ? c.nodes_a[k] : c.node) : UINT32_MAX;
        out.weights_a[k] = k >= a_nodes ? 0.0 : c.feature() ? c.weights_a[k] : 1.0;
    }
    out.sliding = c.sliding ? 1 : 0;
    return out;
}

}  // namespace

extern "C" {

LFEM_API lfem_status lfem_world_query_contacts(const lfem_world* world, lfem_contact* out,
                                               uint32_t capacity, uint32_t* count) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(count, "count");
        require(capacity == 0 || out != nullptr, "out is NULL with a non-zero capacity");
        const std::vector<ContactRecord>& contacts = w.contacts();
        std::size_t active = 0;
        for (const ContactRecord& c : contacts) active += c.active();
        require(active <= UINT32_MAX, "more than 2^32 - 1 active contacts");
        *count = uint32_t(active);
        if (active > capacity)
            throw Error(Status::buffer_too_small, "capacity " + std::to_string(capacity) + " is below the " +
                                                   std::to_string(active) + " active contacts");
        std::size_t i = 0;
        for (const ContactRecord& c : contacts)
            if (c.active()) out[i++] = contact_as_c(w, c);
        // The list runs in the bodies' internal node order (node_ordering.h); the caller is
        // promised (body_a, node) in its own numbering. A node's contacts with several bodies
        // keep their order (body_b, then shape). No std::stable_sort: its scratch buffer comes
        // from a nothrow new.
        auto key = [](const lfem_contact& c) {
            return std::make_tuple(c.body_a.index, c.node, c.body_b.index, c.shape, c.kind, c.triangle[0], c.triangle[1],
                                   c.triangle[2]);
        };
        std::sort(out, out + active, [&](const lfem_contact& p, const lfem_contact& q) { return key(p) < key(q); });
    });
}

}  // extern "C"
