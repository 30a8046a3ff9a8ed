// Self-contact (issue 15): with lfem_body_def.self_contact, a body's boundary nodes meet its own
// boundary triangles (all but those around the node) through the same multipliers as contact
// between bodies. Three scenes of the issue: a soft bar folding over a thin rod, a jelly column
// squashed flat, a soft strip dropped on end that piles on itself.
//
// What "passing through itself" means here, measured from outside the library after every
// 1/60 s call: a boundary node lying in one of the body's own tets (not one of its own), by its
// distance from the body's surface (depth_inside, lfem_test_util.h): its true depth, however
// the tets around it are cut. A node counts as inside when that depth exceeds 0.02 of the mean
// boundary edge l: twenty times the depth a resting contact is allowed (1e-3 l), so nodes lying
// on their own folds never count. The same scenes without self-contact have many such nodes,
// so the measure would see a failure.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

uint32_t self_contacts(lfem_world* w) {
    uint32_t count = 0, self = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);  // the count (LFEM_BUFFER_TOO_SMALL when any)
    std::vector<lfem_contact> contacts(count);
    EXPECT_EQ(lfem_world_query_contacts(w, contacts.data(), count, &count), LFEM_OK);
    for (const lfem_contact& c : contacts) self += c.body_a.index == c.body_b.index;
    return self;
}

// What a run showed: the most nodes inside and the deepest, after any call; the same at the
// end; the most self-contacts after any call.
struct Fold {
    int worst_count = 0;
    double worst_depth = 0;
    double worst_edge = 0;  // l, the deepest point of its sharp edges inside itself after any call
    Inside end;
    uint32_t most_self = 0;
    std::vector<double> x_end;
    double lowest = HUGE_VAL, highest = -HUGE_VAL, widest = 0;  // m, at the end
};

// Steps `calls` 1/60 s calls, calling before(i) ahead of call i, and measures after each.
template <class Before>
Fold watch(lfem_world* w, lfem_body b, const Mesh& mesh, int calls, const Before& before) {
    Fold out;
    const std::vector<std::array<uint32_t, 2>> edges = sharp_edges(body_shape(w, b, mesh));
    for (int i = 0; i < calls; ++i) {
        before(i);
        EXPECT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const Inside in = inside_itself(w, b, mesh, edges);
        out.worst_edge = std::max(out.worst_edge, in.deepest_edge);
        out.worst_count = std::max(out.worst_count, in.count);
        out.worst_depth = std::max(out.worst_depth, in.deepest);
        out.end = in;
        out.most_self = std::max(out.most_self, self_contacts(w));
    }
    out.x_end = positions(w, b);
    double xmin = HUGE_VAL, xmax = -HUGE_VAL;
    for (size_t k = 0; k < out.x_end.size(); k += 3) {
        xmin = std::min(xmin, out.x_end[k]), xmax = std::max(xmax, out.x_end[k]);
        out.lowest = std::min(out.lowest, out.x_end[k + 2]), out.highest = std::max(out.highest, out.x_end[k + 2]);
    }
    out.widest = xmax - xmin;
    return out;
}

// A soft bar (0.6 x 0.03 x 0.03 m, 24 x 2 x 2 cells, E = 2e4 Pa, corotational) dropped across
// a thin static rod (a capsule of radius 5 mm along y, 0.4 m above a floor): it folds over the
// rod and its halves swing in and meet below it.
Fold bar_over_rod(bool self_contact, uint32_t threads = 1, int calls = 90) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    World w(wd);
    add_plane_floor(w);
    lfem_body_def sd = lfem_body_def_default();
    sd.type = LFEM_BODY_STATIC;
    lfem_body rod{};
    EXPECT_EQ(lfem_body_create(w, &sd, &rod), LFEM_OK);
    lfem_shape_def capsule = lfem_shape_def_default();
    capsule.type = LFEM_SHAPE_CAPSULE;
    capsule.radius = 0.005;
    capsule.half_length = 0.1;
    capsule.center[2] = 0.4;
    capsule.rotation[0] = capsule.rotation[1] = std::sqrt(0.5);  // local z along world y
    capsule.rotation[2] = capsule.rotation[3] = 0.0;
    EXPECT_EQ(lfem_body_add_shape(w, rod, &capsule, nullptr), LFEM_OK) << lfem_last_error();
    Mesh bar;
    make_box_mesh(bar, 0.6, 0.03, 0.03, 24, 2, 2, -0.3, -0.015, 0.406);
    const lfem_body b = add_body(w, soft_def(LFEM_MODEL_COROTATIONAL, 2e4, 0.3, 2, 0.3, self_contact), bar);
    return watch(w, b, bar, calls, [](int) {});
}

// A jelly column (4 x 4 x 16 cm, 3 x 3 x 12 cells, E = 1e3 Pa, nu = 0.45, damping 10) on a floor,
// squashed by a kinematic plate (a box shape) at 0.2 m/s to a fifth of its height, then held:
// it buckles, and its sides fold onto themselves in tight creases.
Fold jelly_column(lfem_model model, double friction, bool self_contact) {
    World w;
    add_plane_floor(w);
    Mesh column;
    make_box_mesh(column, 0.04, 0.04, 0.16, 3, 3, 12, -0.02, -0.02, 0.0);
    const lfem_body b = add_body(w, soft_def(model, 1e3, 0.45, 10, friction, self_contact), column);
    lfem_body_def pd = lfem_body_def_default();
    pd.type = LFEM_BODY_KINEMATIC;
    pd.friction = friction;
    lfem_body plate{};
    EXPECT_EQ(lfem_body_create(w, &pd, &plate), LFEM_OK);
    lfem_shape_def box = lfem_shape_def_default();
    box.type = LFEM_SHAPE_BOX;
    box.half_extents[0] = box.half_extents[1] = 0.2;
    box.half_extents[2] = 0.01;
    box.center[2] = 0.16 + 0.01 + 0.001;
    EXPECT_EQ(lfem_body_add_shape(w, plate, &box, nullptr), LFEM_OK) << lfem_last_error();
    const double speed = 0.2, travel = 0.8 * 0.16 + 0.001, dt = 1.0 / 60;
    double moved = 0;
    return watch(w, b, column, 90, [&](int) {
        double v[3] = {0, 0, 0};
        const double omega[3] = {0, 0, 0};
        if (moved < travel) v[2] = -std::min(speed, (travel - moved) / dt), moved -= v[2] * dt;
        EXPECT_EQ(lfem_body_set_kinematic_velocity(w, plate, v, omega), LFEM_OK);
    });
}

// A soft strip (30 x 6 x 1 cm, 30 x 6 x 2 cells, E = 1e4 Pa, damping 2) standing on end 2 mm
// above a floor, falling at v0 and tipping over (1 rad/s about y): it buckles on landing and
// piles up in folds a few cells across, its faces pressed on each other.
Fold strip_on_end(lfem_model model, double v0, bool self_contact) {
    World w;
    add_plane_floor(w);
    Mesh strip;
    make_box_mesh(strip, 0.01, 0.06, 0.3, 2, 6, 30, -0.005, -0.03, 0.002);
    lfem_body_def d = soft_def(model, 1e4, 0.3, 2, 0.5, self_contact);
    d.linear_velocity[2] = -v0;
    d.angular_velocity[1] = 1.0;
    const lfem_body b = add_body(w, d, strip);
    return watch(w, b, strip, 60, [](int) {});
}

// A fold scene kept apart: no boundary node inside its own body after any call (0.02 l, see the
// top of the file), and the body's parts did press on each other (self-contacts carried force).
void expect_kept_apart(const Fold& f, const char* what) {
    EXPECT_EQ(f.worst_count, 0) << what << ": the deepest " << f.worst_depth << " l";
    EXPECT_GT(f.most_self, 10u) << what;
}

}  // namespace

TEST(SelfContact, ASoftBarFoldsOverARodWithoutPassingThroughItself) {
    const Fold with = bar_over_rod(true), without = bar_over_rod(false);
    std::printf("bar over a rod: at worst %d boundary nodes inside itself with self-contact (deepest %.3f l, %u "
                "self-contacts at most), %d without (deepest %.3f l)\n",
                with.worst_count, with.worst_depth, with.most_self, without.worst_count, without.worst_depth);
    expect_kept_apart(with, "bar");        // and its halves did meet
    EXPECT_GT(without.worst_count, 0);    // and without self-contact they pass through each other
    // It hangs folded over the rod: its top on the rod (0.4 m + 5 mm), its halves side by side
    // below it (0.6 m of bar within a few thicknesses across), clear of the floor.
    EXPECT_GT(with.highest, 0.405);
    EXPECT_LT(with.highest, 0.45);
    EXPECT_LT(with.widest, 0.2);
    EXPECT_GT(with.lowest, 0.05);
}

// Each fold scene with self-contact, for two models and two frictions (the column) or two
// speeds (the strip); and once without it, where the measure must see the body pass through
// itself.
using FoldCase = std::tuple<lfem_model, double>;

Fold fold_scene(const std::string& scene, lfem_model model, double value, bool self_contact) {
    return scene == "jelly column" ? jelly_column(model, value, self_contact) : strip_on_end(model, value, self_contact);
}

class FoldScene : public ::testing::TestWithParam<FoldCase> {
protected:
    void run(const char* scene, const char* parameter) {
        const lfem_model model = std::get<0>(GetParam());
        const double value = std::get<1>(GetParam());
        const Fold f = fold_scene(scene, model, value, true);
        std::printf("%s, %s, %s %.1f: at worst %d nodes inside itself (deepest %.3f l), %d at the end; %u "
                    "self-contacts at most; sharp edges at worst %.3f l deep\n",
                    scene, model_name(model), parameter, value, f.worst_count, f.worst_depth, f.end.count, f.most_self,
                    f.worst_edge);
        expect_kept_apart(f, scene);
    }
};

class JellyColumn : public FoldScene {};
class StripOnEnd : public FoldScene {};

// The column's folds press flat on each other and stay apart at every call.
TEST_P(JellyColumn, SquashedFlatKeepsItsFoldsApart) { run("jelly column", "friction"); }
TEST_P(StripOnEnd, DroppedOnTheFloorPilesOnItselfWithoutPassingThrough) { run("strip on end", "m/s"); }

INSTANTIATE_TEST_SUITE_P(ModelsAndFriction, JellyColumn,
                         ::testing::Combine(::testing::Values(LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_COROTATIONAL),
                                            ::testing::Values(0.5, 2.0)));
INSTANTIATE_TEST_SUITE_P(ModelsAndSpeeds, StripOnEnd,
                         ::testing::Combine(::testing::Values(LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_COROTATIONAL),
                                            ::testing::Values(1.0, 2.0)));

TEST(SelfContact, WithoutItTheFoldScenesPassThroughThemselves) {
    for (const char* scene : {"jelly column", "strip on end"}) {
        const Fold f = fold_scene(scene, LFEM_MODEL_NEO_HOOKEAN, scene[0] == 'j' ? 0.5 : 2.0, false);
        std::printf("%s without self-contact: at worst %d nodes inside itself (deepest %.3f l)\n", scene,
                    f.worst_count, f.worst_depth);
        EXPECT_GT(f.worst_count, 10) << scene;
    }
}

TEST(SelfContact, IsBitwiseTheSameOnOneAndTwoThreads) {
    const Fold one = bar_over_rod(true, 1, 40), two = bar_over_rod(true, 2, 40);
    ASSERT_EQ(one.x_end.size(), two.x_end.size());
    EXPECT_EQ(0, std::memcmp(one.x_end.data(), two.x_end.data(), one.x_end.size() * sizeof(double)));
}

TEST(SelfContact, IsRefusedForBodiesThatKeepTheirShapeAndForValuesOtherThanZeroOrOne) {
    World w;
    for (lfem_body_type type : {LFEM_BODY_STATIC, LFEM_BODY_KINEMATIC, LFEM_BODY_RIGID}) {
        lfem_body_def d = lfem_body_def_default();
        d.type = type;
        d.self_contact = 1;
        lfem_body b{};
        EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_INVALID_ARGUMENT) << type;
        EXPECT_NE(std::string(lfem_last_error()).find("self_contact"), std::string::npos) << lfem_last_error();
    }
    lfem_body_def d = lfem_body_def_default();
    d.self_contact = 2;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(stats(w).body_count, 0u);  // nothing was created
}
