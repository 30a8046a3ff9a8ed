#include "contact/link_constraint.h"

#include <algorithm>

namespace lfem {

namespace {

LinkSide side_of(const ContactBody& b, const LinkNodes& n) {
    LinkSide s;
    s.count = n.count;
    for (uint32_t k = 0; k < n.count; ++k) s.point[k] = point_of(b, n.node[k]), s.weight[k] = n.weight[k];
    return s;
}

}  // namespace

void make_link_pairs(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     std::vector<LinkRecord>& links, std::vector<LinkPair>& pairs) {
    pairs.assign(links.size(), LinkPair{});
    for (std::size_t k = 0; k < links.size(); ++k) {
        LinkRecord& l = links[k];
        LinkPair& p = pairs[k];
        p.node = side_of(bodies[body_of_slot[l.body_a]], l.held);
        p.target.count = 1, p.target.weight[0] = 1.0;
        if (l.target_nodes.count > 0) {
            p.target = side_of(bodies[body_of_slot[l.body_b]], l.target_nodes);
        } else if (l.body_b != UINT32_MAX && bodies[body_of_slot[l.body_b]].rigid) {
            p.target.point[0].rigid = bodies[body_of_slot[l.body_b]].rigid;
            p.target.point[0].x = l.target;  // its predicted place: read, never written (push_rigid)
        } else {
            p.target.point[0].x = l.target;  // fixed in the solve: never written (w = 0)
        }
    }
}

void warm_start_link(const LinkRecord& link, LinkPair& pair) {
    const Vec3 lambda(link.lambda);
    pair.node.push(lambda);
    pair.target.push(-lambda);
}

double update_link(LinkRecord& link, LinkPair& pair) {
    double largest = 0.0;
    for (int d = 0; d < 3; ++d) {
        const Vec3 e = Vec3::Unit(d);
        const double H = pair.node.response(e) + pair.target.response(e) + link.compliance;
        if (!(H > 0.0)) continue;  // both ends immovable along d, and a hard link
        double r = pair.node.position()[d] - pair.target.position()[d];
        if (link.compliance > 0.0) r += link.compliance * link.lambda[d] - link.start_share * link.r0[d];
        const double step = -r / H;
        link.lambda[d] += step;
        largest = std::max({largest, pair.node.push(step * e), pair.target.push(-step * e)});
    }
    return largest;
}

}  // namespace lfem
