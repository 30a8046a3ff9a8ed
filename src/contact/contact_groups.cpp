#include "contact/contact_groups.h"

namespace lfem {
namespace {

// Union-find root of body i (path halving).
uint32_t root_of(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// The members of each group in list order (a counting sort): order[begin[g] .. begin[g+1]).
void sort_by_group(const std::vector<uint32_t>& group_of, uint32_t groups, std::vector<uint32_t>& begin,
                   std::vector<uint32_t>& order, std::vector<uint32_t>& next) {
    begin.assign(groups + 1, 0);
    order.resize(group_of.size());
    for (uint32_t g : group_of) ++begin[g + 1];
    for (uint32_t g = 0; g < groups; ++g) begin[g + 1] += begin[g];
    next.assign(begin.begin(), begin.end() - 1);
    for (std::size_t j = 0; j < group_of.size(); ++j) order[next[group_of[j]]++] = uint32_t(j);
}

}  // namespace

void find_groups(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                 uint32_t record_count, const std::vector<RecordRun>& record_runs,
                 const std::vector<LinkRecord>& links, ContactGroups& s) {
    const uint32_t nb = uint32_t(bodies.size());
    std::vector<uint32_t>& parent = s.parent;
    std::vector<uint8_t>& movable = s.movable;
    parent.resize(nb);
    movable.resize(nb);
    for (uint32_t i = 0; i < nb; ++i) parent[i] = i, movable[i] = is_movable(bodies[i]);
    // The work below is done once per run (a few dozen runs for hundreds of records).
    std::vector<ContactGroups::Run>& runs = s.runs;
    runs.clear();
    for (const RecordRun& r : record_runs) runs.push_back({r.first, body_of_slot[r.body_a], body_of_slot[r.body_b], 0});
    auto link_bodies = [&](uint32_t a, uint32_t b) {
        if (movable[a] && movable[b]) parent[root_of(parent, a)] = root_of(parent, b);
    };
    for (const ContactGroups::Run& r : runs) link_bodies(r.a, r.b);
    for (const LinkRecord& l : links)
        if (l.body_b != UINT32_MAX) link_bodies(body_of_slot[l.body_a], body_of_slot[l.body_b]);
    // A pair's group is that of its movable body (the node's, or else the triangle's), numbered
    // in the order of their first body. (Numbered in order of first appearance in the list, where
    // a static floor's nodes come first, the cubes on the floor were scattered over both threads,
    // and their nodes crossed between the cores twice a sub-step.)
    std::vector<uint32_t>& group_of_root = s.group_of_root;
    constexpr uint32_t kNone = UINT32_MAX, kUsed = UINT32_MAX - 1;
    group_of_root.assign(nb, kNone);
    const auto root_of_pair = [&](uint32_t a, uint32_t b) { return root_of(parent, b == kNone || movable[a] ? a : b); };
    const auto slot_body = [&](uint32_t slot) { return slot == kNone ? kNone : body_of_slot[slot]; };
    for (const ContactGroups::Run& r : runs) group_of_root[root_of_pair(r.a, r.b)] = kUsed;
    for (const LinkRecord& l : links) group_of_root[root_of_pair(slot_body(l.body_a), slot_body(l.body_b))] = kUsed;
    uint32_t groups = 0;
    for (uint32_t i = 0; i < nb; ++i) {
        uint32_t& group = group_of_root[root_of(parent, i)];
        if (group == kUsed) group = groups++;
    }
    const auto group_of = [&](uint32_t a, uint32_t b) { return group_of_root[root_of_pair(a, b)]; };
    // Each group's records in list order (a counting sort by runs).
    std::vector<uint32_t>& begin = s.begin;
    begin.assign(groups + 1, 0);
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const uint32_t end = k + 1 < runs.size() ? runs[k + 1].first : record_count;
        runs[k].group = group_of(runs[k].a, runs[k].b);
        begin[runs[k].group + 1] += end - runs[k].first;
    }
    for (uint32_t g = 0; g < groups; ++g) begin[g + 1] += begin[g];
    s.next.assign(begin.begin(), begin.end() - 1);
    s.order.resize(record_count);
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const uint32_t end = k + 1 < runs.size() ? runs[k + 1].first : record_count;
        uint32_t& next = s.next[runs[k].group];
        for (uint32_t j = runs[k].first; j < end; ++j) s.order[next++] = j;
    }
    s.group_of_link.resize(links.size());
    for (std::size_t j = 0; j < links.size(); ++j)
        s.group_of_link[j] = group_of(slot_body(links[j].body_a), slot_body(links[j].body_b));
    sort_by_group(s.group_of_link, groups, s.link_begin, s.link_order, s.next);
}

}  // namespace lfem
