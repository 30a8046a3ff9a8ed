#include "contact/group_partition.h"

#include <algorithm>

namespace lfem {
namespace {

constexpr uint32_t kNone = UINT32_MAX;
constexpr uint32_t kMaxParts = 8;

// The parts of the pair's two bodies (kNone for a body that does not move in the solve).
void parts_of(const GroupPartition& p, const std::vector<uint32_t>& body_of_slot, const ContactRecord& r,
              uint32_t& pa, uint32_t& pb) {
    pa = p.part_of_body[body_of_slot[r.body_a]];
    pb = p.part_of_body[body_of_slot[r.body_b]];
}

}  // namespace

bool partition_group(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     const std::vector<ContactRecord>& records, uint32_t* order, uint32_t count, GroupPartition& p) {
    if (count < kPartitionPairs) return false;
    // The group's movable bodies, sorted by the x of their first node, then by slot.
    p.part_of_body.assign(bodies.size(), kNone);
    p.sorted.clear();
    for (uint32_t k = 0; k < count; ++k) {
        const ContactRecord& r = records[order[k]];
        for (uint32_t slot : {r.body_a, r.body_b}) {
            const uint32_t i = body_of_slot[slot];
            if (!is_movable(bodies[i]) || p.part_of_body[i] != kNone) continue;
            p.part_of_body[i] = 0;  // met
            p.sorted.push_back(GroupPartition::Body{bodies[i].x[0], slot, i});
        }
    }
    const uint32_t n = uint32_t(p.sorted.size());
    if (n < kPartitionBodies) {
        for (const GroupPartition::Body& b : p.sorted) p.part_of_body[b.index] = kNone;
        return false;
    }
    std::sort(p.sorted.begin(), p.sorted.end(), [](const GroupPartition::Body& u, const GroupPartition::Body& v) {
        return u.x != v.x ? u.x < v.x : u.slot < v.slot;
    });
    const uint32_t parts = std::min(kMaxParts, n / 4);
    for (uint32_t j = 0; j < n; ++j) p.part_of_body[p.sorted[j].index] = uint32_t(uint64_t(j) * parts / n);
    // The pairs between two parts: their edges (a * parts + b, a < b), coloured greedily in edge
    // order with the first colour neither part has yet.
    p.edges.clear();
    for (uint32_t k = 0; k < count; ++k) {
        uint32_t pa, pb;
        parts_of(p, body_of_slot, records[order[k]], pa, pb);
        if (pa != kNone && pb != kNone && pa != pb) p.edges.push_back(std::min(pa, pb) * parts + std::max(pa, pb));
    }
    std::sort(p.edges.begin(), p.edges.end());
    p.edges.erase(std::unique(p.edges.begin(), p.edges.end()), p.edges.end());
    p.colours_of_part.assign(parts, 0);
    p.colour_of_edge.resize(p.edges.size());
    uint32_t colours = 0;
    for (std::size_t e = 0; e < p.edges.size(); ++e) {
        const uint32_t a = p.edges[e] / parts, b = p.edges[e] % parts;
        const uint64_t used = p.colours_of_part[a] | p.colours_of_part[b];
        uint32_t c = 0;
        while (used >> c & 1u) ++c;  // parts <= 8: fewer than 16 colours
        p.colour_of_edge[e] = c;
        p.colours_of_part[a] |= uint64_t(1) << c, p.colours_of_part[b] |= uint64_t(1) << c;
        colours = std::max(colours, c + 1);
    }
    // Tasks: the parts' own pairs (phase 0), then the edges colour by colour (phase 1 + c).
    std::vector<uint32_t>& task_of_edge = p.task_of_edge;
    task_of_edge.resize(p.edges.size());
    p.phase_begin.assign(1, 0);
    p.phase_begin.push_back(parts);
    uint32_t tasks = parts;
    for (uint32_t c = 0; c < colours; ++c) {
        for (std::size_t e = 0; e < p.edges.size(); ++e)
            if (p.colour_of_edge[e] == c) task_of_edge[e] = tasks++;
        p.phase_begin.push_back(tasks);
    }
    p.task_of_pair.resize(count);
    for (uint32_t k = 0; k < count; ++k) {
        uint32_t pa, pb;
        parts_of(p, body_of_slot, records[order[k]], pa, pb);
        if (pa == kNone && pb == kNone) p.task_of_pair[k] = 0;  // nothing moves: any task
        else if (pa == kNone || pa == pb) p.task_of_pair[k] = pb;
        else if (pb == kNone) p.task_of_pair[k] = pa;
        else {
            const uint32_t key = std::min(pa, pb) * parts + std::max(pa, pb);
            p.task_of_pair[k] = task_of_edge[std::lower_bound(p.edges.begin(), p.edges.end(), key) - p.edges.begin()];
        }
    }
    // A stable counting sort of the records by task.
    p.task_begin.assign(tasks + 1, 0);
    for (uint32_t k = 0; k < count; ++k) ++p.task_begin[p.task_of_pair[k] + 1];
    for (uint32_t t = 0; t < tasks; ++t) p.task_begin[t + 1] += p.task_begin[t];
    p.next.assign(p.task_begin.begin(), p.task_begin.end() - 1);
    p.moved.resize(count);
    for (uint32_t k = 0; k < count; ++k) p.moved[p.next[p.task_of_pair[k]]++] = order[k];
    std::copy(p.moved.begin(), p.moved.end(), order);
    return true;
}

}  // namespace lfem
