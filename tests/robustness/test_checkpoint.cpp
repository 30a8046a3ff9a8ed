// Checkpoints (lfem_world_save / lfem_world_load): a run continued from a checkpoint is
// bitwise identical to one that never stopped, and a damaged file is refused with
// LFEM_IO_ERROR without creating anything.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "robustness/robustness_scene.h"

using namespace lfem_test;

namespace {

std::string temp_path(const char* name) {
    return std::string(::testing::TempDir()) + "lfem_" + name + ".ckpt";
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_all(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

// A load that must fail: LFEM_IO_ERROR, a message, and *out untouched.
void expect_refused(const std::string& path, const char* what) {
    lfem_world* sentinel = reinterpret_cast<lfem_world*>(uintptr_t(0x1234));
    lfem_world* out = sentinel;
    EXPECT_EQ(lfem_world_load(path.c_str(), &out), LFEM_IO_ERROR) << what;
    EXPECT_EQ(out, sentinel) << what;
    EXPECT_NE(std::string(lfem_last_error()).find("checkpoint"), std::string::npos) << what;
}

}  // namespace

TEST(Checkpoint, ContinuedRunIsBitwiseIdentical) {
    RobustnessScene original;
    EXPECT_GT(original.run(40), 10u);  // in contact when saved: the warm start matters
    const std::string path = temp_path("continue");
    ASSERT_EQ(lfem_world_save(original.w, path.c_str()), LFEM_OK) << lfem_last_error();

    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    // The same state, read through the saved world's own handles.
    EXPECT_EQ(original.state(), fingerprint(loaded, original.bodies));

    // Both go on with steps of another size (sub-step changes included) and must agree bit
    // for bit, contacts and statistics included.
    for (int i = 0; i < 40; ++i) {
        ASSERT_EQ(lfem_world_step(original.w, 0.0037), LFEM_OK) << lfem_last_error();
        ASSERT_EQ(lfem_world_step(loaded, 0.0037), LFEM_OK) << lfem_last_error();
    }
    EXPECT_EQ(original.state(), fingerprint(loaded, original.bodies));
    uint32_t n1 = 0, n2 = 0;
    lfem_world_query_contacts(original.w, nullptr, 0, &n1);
    lfem_world_query_contacts(loaded, nullptr, 0, &n2);
    ASSERT_EQ(n1, n2);
    ASSERT_GT(n1, 0u);
    std::vector<lfem_contact> c1(n1), c2(n2);
    lfem_world_query_contacts(original.w, c1.data(), n1, &n1);
    lfem_world_query_contacts(loaded, c2.data(), n2, &n2);
    EXPECT_EQ(0, std::memcmp(c1.data(), c2.data(), n1 * sizeof(lfem_contact)));

    // The loaded world is a world like any other: bodies can be added, and their handles are
    // new (never one of a destroyed body).
    Mesh extra;
    make_box_mesh(extra, 0.05, 0.05, 0.05, 1, 1, 1, 0.3, 0.3, 0.5);
    const lfem_body added = add_body(loaded, lfem_body_def_default(), extra);
    for (lfem_body b : original.bodies) EXPECT_NE(added.generation, b.generation);
    EXPECT_EQ(lfem_world_step(loaded, 0.005), LFEM_OK) << lfem_last_error();
    lfem_world_destroy(loaded);
    std::remove(path.c_str());
}

TEST(Checkpoint, SavingOverAnExistingCheckpointReplacesItWhole) {
    RobustnessScene scene;
    scene.run(5);
    const std::string path = temp_path("replace");
    ASSERT_EQ(lfem_world_save(scene.w, path.c_str()), LFEM_OK) << lfem_last_error();
    const std::string first = read_all(path);
    // A save that cannot be written (a directory that does not exist) leaves nothing behind
    // and reports LFEM_IO_ERROR.
    const std::string bad = std::string(::testing::TempDir()) + "no/such/dir/x.ckpt";
    EXPECT_EQ(lfem_world_save(scene.w, bad.c_str()), LFEM_IO_ERROR);
    EXPECT_EQ(read_all(path), first);
    scene.run(5);
    ASSERT_EQ(lfem_world_save(scene.w, path.c_str()), LFEM_OK) << lfem_last_error();
    EXPECT_NE(read_all(path), first);
    std::ifstream tmp(path + ".tmp");
    EXPECT_FALSE(tmp.good()) << "the temporary file was left behind";
    std::remove(path.c_str());
}

TEST(Checkpoint, DamagedFilesAreRefused) {
    RobustnessScene scene;
    scene.run(10);
    const std::string path = temp_path("good"), bad = temp_path("bad");
    ASSERT_EQ(lfem_world_save(scene.w, path.c_str()), LFEM_OK) << lfem_last_error();
    const std::string good = read_all(path);
    ASSERT_GT(good.size(), 1000u);

    expect_refused(temp_path("missing_file"), "missing file");
    expect_refused(std::string(::testing::TempDir()), "a directory");
    // Every truncation length up to the header, then a spread of lengths through the payload.
    for (std::size_t n = 0; n < good.size(); n += (n < 64 ? 1 : good.size() / 97 + 1)) {
        write_all(bad, good.substr(0, n));
        expect_refused(bad, "truncated");
    }
    write_all(bad, good + "x");
    expect_refused(bad, "trailing byte");
    // One flipped bit anywhere: in the header (magic, version, layout, sizes, checksum) or the
    // payload (caught by the checksum).
    for (std::size_t i = 0; i < good.size(); i += (i < 64 ? 1 : good.size() / 211 + 1)) {
        std::string damaged = good;
        damaged[i] = char(damaged[i] ^ 0x10);
        write_all(bad, damaged);
        expect_refused(bad, ("bit flipped at byte " + std::to_string(i)).c_str());
    }
    // Not a checkpoint at all.
    write_all(bad, std::string(4096, 'A'));
    expect_refused(bad, "junk");
    // The good file still loads (the refusals above left no state behind).
    lfem_world* w = nullptr;
    EXPECT_EQ(lfem_world_load(path.c_str(), &w), LFEM_OK) << lfem_last_error();
    lfem_world_destroy(w);
    std::remove(path.c_str());
    std::remove(bad.c_str());
}

// A file of another format version (an older lfem's, before 10-node tets) is refused with a
// message that says so, not read as if it were this version's.
TEST(Checkpoint, OtherFormatVersionsAreRefusedWithTheReason) {
    RobustnessScene scene;
    scene.run(2);
    const std::string path = temp_path("version"), bad = temp_path("old_version");
    ASSERT_EQ(lfem_world_save(scene.w, path.c_str()), LFEM_OK) << lfem_last_error();
    const std::string good = read_all(path);
    uint32_t version = 0;
    std::memcpy(&version, good.data() + 8, 4);  // after the 8-byte magic
    for (uint32_t other : {version - 1, version + 1}) {
        std::string edited = good;
        std::memcpy(&edited[8], &other, 4);
        write_all(bad, edited);
        expect_refused(bad, "other format version");
        const std::string message = lfem_last_error();
        EXPECT_NE(message.find("format version " + std::to_string(other)), std::string::npos) << message;
        EXPECT_NE(message.find(other < version ? "older" : "newer"), std::string::npos) << message;
        EXPECT_NE(message.find("reads version " + std::to_string(version)), std::string::npos) << message;
    }
    std::remove(path.c_str());
    std::remove(bad.c_str());
}

TEST(Checkpoint, BadArguments) {
    RobustnessScene scene;
    lfem_world* out = nullptr;
    EXPECT_EQ(lfem_world_save(nullptr, "x"), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_save(scene.w, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_load(nullptr, &out), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_load("x", nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(out, nullptr);
}

// A file altered on purpose, with its checksum made to match: the loader's own checks must
// catch whatever would make a step read out of bounds. Each altered file either loads (the
// change was a harmless number) and can be stepped, or is refused; nothing crashes (this test
// also runs under AddressSanitizer).
TEST(Checkpoint, AlteredFilesWithMatchingChecksumNeverCrash) {
    RobustnessScene scene;
    scene.run(10);
    const std::string path = temp_path("altered_src"), bad = temp_path("altered");
    ASSERT_EQ(lfem_world_save(scene.w, path.c_str()), LFEM_OK) << lfem_last_error();
    const std::string good = read_all(path);
    const std::size_t header = 48, checksum_at = 40;  // see src/world/checkpoint.cpp
    auto fnv1a = [](const std::string& s, std::size_t from) {
        uint64_t h = 1469598103934665603ull;
        for (std::size_t i = from; i < s.size(); ++i) h = (h ^ uint8_t(s[i])) * 1099511628211ull;
        return h;
    };
    uint64_t seed = 12345;
    int loaded = 0, refused = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::string altered = good;
        for (int k = 0; k < 1 + trial % 3; ++k) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            const std::size_t at = header + std::size_t(seed >> 33) % (good.size() - header);
            altered[at] = char(uint8_t(seed >> 20));
        }
        const uint64_t sum = fnv1a(altered, header);
        std::memcpy(&altered[checksum_at], &sum, sizeof sum);
        write_all(bad, altered);
        lfem_world* w = nullptr;
        const lfem_status s = lfem_world_load(bad.c_str(), &w);
        ASSERT_TRUE(s == LFEM_OK || s == LFEM_IO_ERROR) << lfem_status_string(s);
        if (s == LFEM_OK) {
            ++loaded;
            const lfem_status step = lfem_world_step(w, 0.001);
            EXPECT_NE(step, LFEM_INTERNAL_ERROR) << lfem_last_error();
            lfem_world_destroy(w);
        } else {
            ++refused;
        }
    }
    std::printf("altered checkpoints: %d loaded and stepped, %d refused\n", loaded, refused);
    // Both outcomes occur: the test exercises the checks and the stepping of altered worlds.
    EXPECT_GT(loaded, 0);
    EXPECT_GT(refused, 0);
    std::remove(path.c_str());
    std::remove(bad.c_str());
}
