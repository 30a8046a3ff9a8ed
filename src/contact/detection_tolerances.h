// The tolerances of contact detection, all relative to the boundary edge length l of the
// body whose face (or, for rigid shapes, whose node) is tested. Shared by the broad phase,
// which grows its boxes by them, and the narrow phase, which applies them.
#pragma once

#include <cstdint>

namespace lfem {

// l is the pair's contact_length (contact_body.h) for a node against a triangle, the node's own
// body's edge length against a rigid shape.
//
// Capture band: a node up to 0.05 l in front of a face at the end of the step is kept as a
// (possibly inactive) constraint, so resting contacts do not flicker in and out.
constexpr double kCaptureBand = 0.05;
// Depth allowance: a node that starts the step behind a face is that face's only as deep as
// the previous step left that (node, body) pair: a kept overlap or the solver's residual, times
// 1.25, plus 1e-3 l. Any deeper and the node is not inside the body at all: above a thin
// plate, it lies 'behind' the plate's far face by the plate's thickness plus its height, and
// pulling it through would be a disaster. Paths that cross a face in this step are found by
// the crossing test, not by depth.
constexpr double kResidualDepth = 1e-3;
// The depth allowance of a pair the last step left kept_offset deep (m), at contact length l.
inline double allowed_depth(double kept_offset, double l) { return 1.25 * kept_offset + kResidualDepth * l; }
// Bodies created overlapping: a node up to 0.5 l behind a face it was never in contact with is
// taken as inside (and let out gradually) only if nothing of the other body lies between it
// and the face, i.e. the face really is the nearest way out.
constexpr double kInitialDepth = 0.5;
// Edge tolerance: barycentric weights down to -0.01 count as inside, so nodes on a shared edge
// do not drop out of both neighbouring faces.
constexpr double kEdgeTolerance = 0.01;
// Edge band: a node whose point on a face lies within 0.05 (barycentric) of the face's edges,
// or outside it, sits on an edge for the rule that a face turned the same way as the node's
// surface is the far side of that edge (node_face.cpp).
constexpr double kEdgeBand = 0.05;
// Held face: a node the last step held at a face keeps that face while it takes the node and no
// other face of the body in the same plane (within a degree: normals' cosine above kHeldFaceCos)
// is better by more than 1e-5 l (less penetrated, or further in front). A node resting on the
// other body's vertex or edge lies on the faces around it at the same depth but for rounding;
// taking whichever came out best switched its constraint (normal, weights, warm start) between
// them from sub-step to sub-step, which kept two stacked soft cubes ringing at 2e-3 m/s (and the
// solve at its cap) where the margin lets them come to rest (3e-6 m/s). Only in one plane: on
// faces turned from each other (a curved surface, a 10-node body's sub-triangles; a degree or two
// is enough) the better face is better, and a node kept on the worse sat up to the margin inside
// it (0.5 um in a stack of three cubes, against 4e-12 m without).
constexpr double kHeldFaceMargin = 1e-5;
constexpr double kHeldFaceCos = 0.99985;  // cos 1 degree
// Valley: two faces that both hold a node, turned from each other by more than about 10
// degrees (cosine 0.985), each in front of the other's plane (node_face.h, NodeSlots).
constexpr double kValleyCos = 0.985;
// Inside band: a node found inside a deformable body is taken by a face it lies behind while
// its point lies within 0.25 (barycentric) of the triangle: that face is its way out (it may
// lie beyond the edges of every face near it, come in through a crease or past a corner).
constexpr double kInsideBand = 0.25;
// An overlap found at the start of a step is removed over several steps, 20 % per step, but
// never faster than 1e-3 l per step for bodies created overlapping (gently, rather than in one
// violent jump), never faster than 1e-2 l per step for one that came about during the run.
constexpr double kOverlapRecovery = 0.2;
constexpr double kMaxRecovery = 1e-3;
// A node found inside another body during the run (it fell in: a fold, a solve cut short) is
// pushed out faster, at most 1e-2 l per step.
constexpr double kFallenRecovery = 1e-2;

// How much a triangle's box grows over a step for a node at contact length l: the capture band
// plus the deepest overlap being recovered, or half an edge when new bodies are checked for
// initial overlaps.
inline double triangle_growth(double l, double max_offset, bool scan_overlaps) {
    const double band = kCaptureBand * l + max_offset, initial = scan_overlaps ? kInitialDepth * l : 0.0;
    return band > initial ? band : initial;
}

}  // namespace lfem
