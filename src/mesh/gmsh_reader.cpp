// Gmsh .msh reader, ASCII formats 2.2 and 4.1: 4-node (type 4) or 10-node (type 11) tets.
//
// The file is read line by line (Gmsh writes one node coordinate set and one element per
// line), so every error can name its line. Only $MeshFormat, $Nodes and $Elements are
// interpreted; any other section is skipped up to its $End marker. Counts written in the file
// are never trusted for memory: arrays grow as records are actually read, so a hostile count
// ends in "unexpected end of file", not in a huge allocation.
//
// Node tags may be sparse and in any order; they are sorted once and looked up by binary
// search (no hash map whose worst case an adversary could trigger).
#include "mesh/gmsh_reader.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <numeric>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "common/error.h"
#include "common/quadratic_tet_nodes.h"
#include "mesh/quadratic_mesh.h"
#include "mesh/tet_geometry.h"

namespace lfem {
namespace {

constexpr int kGmshTet = 4;     // element type of the 4-node tetrahedron
constexpr int kGmshTet10 = 11;  // element type of the 10-node tetrahedron

// The nodes of an element type that is read (4 or 10), else 0 (skipped).
uint32_t tet_nodes_of_type(int64_t type) {
    return type == kGmshTet ? kLinearTetNodes : type == kGmshTet10 ? kQuadraticTetNodes : 0;
}

// Reads non-blank lines and splits them into whitespace separated tokens.
class LineReader {
public:
    LineReader(std::istream& in, const std::string& path) : in_(in), path_(path) {}

    // false at the end of the file
    bool next() {
        while (std::getline(in_, line_)) {
            ++line_number_;
            split();
            if (!tokens_.empty()) return true;
        }
        if (in_.bad()) fail("read error: " + std::string(std::strerror(errno)));
        tokens_.clear();
        return false;
    }

    // Like next(), but the end of the file is an error inside the named section.
    void next_in(const char* section) {
        if (!next()) fail(std::string("unexpected end of file in ") + section);
    }

    const std::vector<std::string_view>& tokens() const { return tokens_; }
    std::size_t line_number() const { return line_number_; }

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(Status::io_error, path_ + ":" + std::to_string(line_number_) + ": " + what);
    }

    void expect_token_count(std::size_t count, const char* record) const {
        if (tokens_.size() != count)
            fail(std::string("expected ") + std::to_string(count) +
                 (count == 1 ? " field in " : " fields in ") + record + ", found " +
                 std::to_string(tokens_.size()));
    }

    // The current line must be the single token `marker` (e.g. "$EndNodes").
    void expect_marker(const char* marker) const {
        if (tokens_[0] != marker)
            fail(std::string("expected ") + marker + ", found '" + excerpt(0) + "'");
        expect_alone();
    }

    // Section markers stand alone on their line.
    void expect_alone() const {
        if (tokens_.size() != 1) fail("unexpected text '" + excerpt(1) + "' after " + excerpt(0));
    }

    // Field i as a number of type T (from_chars: no locale, no leading '+' for integers);
    // `kind` says what it must be ("a non-negative integer", ...).
    template <class T>
    T number_at(std::size_t i, const char* what, const char* kind) const {
        std::string_view t = tokens_[i];
        if (std::is_floating_point<T>::value && t.size() > 1 && t[0] == '+') t.remove_prefix(1);  // a real may have one
        T value = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec == std::errc::result_out_of_range) fail(std::string(what) + " '" + excerpt(i) + "' is out of range");
        if (ec != std::errc() || end != t.data() + t.size())
            fail(std::string(what) + " '" + excerpt(i) + "' is not " + kind);
        return value;
    }
    uint64_t unsigned_at(std::size_t i, const char* what) const {
        return number_at<uint64_t>(i, what, "a non-negative integer");
    }
    int64_t integer_at(std::size_t i, const char* what) const { return number_at<int64_t>(i, what, "an integer"); }
    double real_at(std::size_t i, const char* what) const {
        const double value = number_at<double>(i, what, "a number");
        if (!std::isfinite(value)) fail(std::string(what) + " '" + excerpt(i) + "' is not finite");
        return value;
    }

    // Token i for a message, cut short so a hostile line cannot make a huge message.
    std::string excerpt(std::size_t i) const {
        const std::string_view t = tokens_[i];
        return t.size() <= 40 ? std::string(t) : std::string(t.substr(0, 40)) + "...";
    }

private:
    void split() {
        tokens_.clear();
        const std::size_t n = line_.size();
        for (std::size_t i = 0; i < n;) {
            while (i < n && is_space(line_[i])) ++i;
            const std::size_t start = i;
            while (i < n && !is_space(line_[i])) ++i;
            if (i > start) tokens_.emplace_back(line_.data() + start, i - start);
        }
    }
    static bool is_space(char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
    }

    std::istream& in_;
    const std::string& path_;
    std::string line_;
    std::vector<std::string_view> tokens_;
    std::size_t line_number_ = 0;
};

// Node and tet records as read, before tags are resolved.
struct RawMesh {
    std::vector<uint64_t> node_tags;
    std::vector<double> node_positions;   // 3 per node
    std::vector<std::size_t> node_lines;  // where each node was defined
    std::vector<uint64_t> tet_tags;       // nodes_per_tet node tags per tet, as in the file
    std::vector<std::size_t> tet_lines;
    uint32_t nodes_per_tet = 0;           // of the first tet read; every other must match
};

// A record that starts with '$' where data was expected means the section ended early.
void require_data_line(const LineReader& r, const char* section, uint64_t expected, uint64_t found,
                       const char* what) {
    if (r.tokens()[0].front() == '$')
        r.fail(std::string("truncated ") + section + " section: expected " +
               std::to_string(expected) + " " + what + ", found " + std::to_string(found));
}

void add_node(RawMesh& raw, const LineReader& r, uint64_t tag, std::size_t first_coordinate) {
    raw.node_tags.push_back(tag);
    for (int i = 0; i < 3; ++i)
        raw.node_positions.push_back(r.real_at(first_coordinate + i, "coordinate"));
    raw.node_lines.push_back(r.line_number());
}

void add_tet(RawMesh& raw, const LineReader& r, std::size_t first_node, uint32_t nodes) {
    if (raw.nodes_per_tet == 0) raw.nodes_per_tet = nodes;
    if (raw.nodes_per_tet != nodes)
        r.fail("the file mixes 4-node and 10-node tetrahedra (element types 4 and 11); a mesh has one kind");
    for (uint32_t i = 0; i < nodes; ++i) raw.tet_tags.push_back(r.unsigned_at(first_node + i, "node tag"));
    raw.tet_lines.push_back(r.line_number());
}

// ---- format 2.2 ----------------------------------------------------------------------------

// A section of format 2.2: the count, then `record` called on each of the count lines, then
// the end marker.
template <class Record>
void read_counted_section(LineReader& r, const char* section, const char* end_marker, const std::string& items,
                          const Record& record) {
    r.next_in(section);
    r.expect_token_count(1, ("the " + items + " count").c_str());
    const uint64_t count = r.unsigned_at(0, (items + " count").c_str());
    for (uint64_t i = 0; i < count; ++i) {
        r.next_in(section);
        require_data_line(r, section, count, i, (items + "s").c_str());
        record();
    }
    r.next_in(section);
    r.expect_marker(end_marker);
}

// count, then "tag x y z" per node
void read_nodes_v2(LineReader& r, RawMesh& raw) {
    read_counted_section(r, "$Nodes", "$EndNodes", "node", [&] {
        r.expect_token_count(4, "a node (tag x y z)");
        add_node(raw, r, r.unsigned_at(0, "node tag"), 1);
    });
}

// count, then "tag type tag_count tags... nodes..." per element
void read_elements_v2(LineReader& r, RawMesh& raw) {
    read_counted_section(r, "$Elements", "$EndElements", "element", [&] {
        const std::size_t fields = r.tokens().size();
        if (fields < 3) r.expect_token_count(3, "an element header (tag type tag_count)");
        r.unsigned_at(0, "element tag");
        const uint32_t nodes = tet_nodes_of_type(r.integer_at(1, "element type"));
        if (nodes == 0) return;  // not a tet: skipped
        const uint64_t tag_count = r.unsigned_at(2, "tag count");
        if (tag_count > fields) r.fail("tag count " + r.excerpt(2) + " exceeds the line");
        r.expect_token_count(3 + std::size_t(tag_count) + nodes, "a tetrahedron");
        add_tet(raw, r, 3 + std::size_t(tag_count), nodes);
    });
}

// ---- format 4.1 ----------------------------------------------------------------------------

// "blocks nodes min_tag max_tag", then per block "dim entity parametric count", the count
// tags one per line, then the count coordinate lines (x y z, plus dim parametric
// coordinates when parametric is 1).
// The section header of format 4.1, "blocks items min_tag max_tag" (items: "node" or
// "element"): the block count and the total.
std::pair<uint64_t, uint64_t> read_section_header(LineReader& r, const char* section, const std::string& items) {
    r.next_in(section);
    const std::string header = "the " + std::string(section) + " header (blocks " + items + "s min_tag max_tag)";
    r.expect_token_count(4, header.c_str());
    const uint64_t blocks = r.unsigned_at(0, "block count");
    const uint64_t total = r.unsigned_at(1, (items + " count").c_str());
    r.unsigned_at(2, ("minimum " + items + " tag").c_str());
    r.unsigned_at(3, ("maximum " + items + " tag").c_str());
    return {blocks, total};
}

// A block header of format 4.1, "dim entity <third> count" (third: the parametric flag of a
// node block, the element type of an element block), block b of `blocks`: returns the count,
// the checked dimension in dim.
uint64_t read_block_header(LineReader& r, const char* section, uint64_t blocks, uint64_t b, const std::string& items,
                           const char* third, uint64_t& dim) {
    r.next_in(section);
    require_data_line(r, section, blocks, b, (items + " blocks").c_str());
    const std::string header =
        (items == "element" ? "an " : "a ") + items + " block header (dim entity " + third + " count)";
    r.expect_token_count(4, header.c_str());
    dim = r.unsigned_at(0, "entity dimension");
    r.unsigned_at(1, "entity tag");
    const uint64_t count = r.unsigned_at(3, (items + " count").c_str());
    if (dim > 3) r.fail("entity dimension " + r.excerpt(0) + " is not 0, 1, 2 or 3");
    return count;
}

void read_nodes_v4(LineReader& r, RawMesh& raw) {
    const auto [blocks, total] = read_section_header(r, "$Nodes", "node");
    uint64_t read = 0;
    std::vector<uint64_t> block_tags;
    for (uint64_t b = 0; b < blocks; ++b) {
        uint64_t dim = 0;
        const uint64_t count = read_block_header(r, "$Nodes", blocks, b, "node", "parametric", dim);
        const uint64_t parametric = r.unsigned_at(2, "parametric flag");
        if (parametric > 1) r.fail("parametric flag " + r.excerpt(2) + " is not 0 or 1");
        block_tags.clear();
        for (uint64_t n = 0; n < count; ++n) {
            r.next_in("$Nodes");
            require_data_line(r, "$Nodes", count, n, "node tags in the block");
            r.expect_token_count(1, "a node tag");
            block_tags.push_back(r.unsigned_at(0, "node tag"));
        }
        const std::size_t fields = 3 + (parametric ? std::size_t(dim) : 0);
        for (uint64_t n = 0; n < count; ++n) {
            r.next_in("$Nodes");
            require_data_line(r, "$Nodes", count, n, "coordinate lines in the block");
            r.expect_token_count(fields, "a node's coordinates");
            for (std::size_t i = 3; i < fields; ++i) r.real_at(i, "parametric coordinate");
            add_node(raw, r, block_tags[n], 0);
        }
        read += count;
    }
    if (read != total)
        r.fail("the $Nodes header announces " + std::to_string(total) +
               " nodes but its blocks hold " + std::to_string(read));
    r.next_in("$Nodes");
    r.expect_marker("$EndNodes");
}

// "blocks elements min_tag max_tag", then per block "dim entity type count" and count lines
// "tag node_tags...".
void read_elements_v4(LineReader& r, RawMesh& raw) {
    const auto [blocks, total] = read_section_header(r, "$Elements", "element");
    uint64_t read = 0;
    for (uint64_t b = 0; b < blocks; ++b) {
        uint64_t dim = 0;
        const uint64_t count = read_block_header(r, "$Elements", blocks, b, "element", "type", dim);
        const uint32_t nodes = tet_nodes_of_type(r.integer_at(2, "element type"));
        const std::string record = "a tetrahedron (tag and " + std::to_string(nodes) + " node tags)";
        for (uint64_t e = 0; e < count; ++e) {
            r.next_in("$Elements");
            require_data_line(r, "$Elements", count, e, "elements in the block");
            r.unsigned_at(0, "element tag");
            if (nodes == 0) continue;  // other cell types are skipped
            r.expect_token_count(1 + nodes, record.c_str());
            add_tet(raw, r, 1, nodes);
        }
        read += count;
    }
    if (read != total)
        r.fail("the $Elements header announces " + std::to_string(total) +
               " elements but its blocks hold " + std::to_string(read));
    r.next_in("$Elements");
    r.expect_marker("$EndElements");
}

// ---- from tags to a dense mesh ---------------------------------------------------------------

[[noreturn]] void fail_at(const std::string& path, std::size_t line, const std::string& what) {
    throw Error(Status::io_error, path + ":" + std::to_string(line) + ": " + what);
}

TetMesh resolve(const RawMesh& raw, const std::string& path, std::size_t last_line) {
    // Nodes sorted by tag; the dense numbering follows the tags, so files listing the same
    // nodes in different orders give the same mesh.
    const std::size_t node_count = raw.node_tags.size();
    std::vector<std::size_t> by_tag(node_count);
    std::iota(by_tag.begin(), by_tag.end(), std::size_t(0));
    std::sort(by_tag.begin(), by_tag.end(), [&](std::size_t a, std::size_t b) {
        const uint64_t ta = raw.node_tags[a], tb = raw.node_tags[b];
        return ta != tb ? ta < tb : raw.node_lines[a] < raw.node_lines[b];
    });
    for (std::size_t i = 1; i < node_count; ++i)
        if (raw.node_tags[by_tag[i]] == raw.node_tags[by_tag[i - 1]])
            fail_at(path, raw.node_lines[by_tag[i]],
                    "node tag " + std::to_string(raw.node_tags[by_tag[i]]) +
                        " is defined twice (first on line " +
                        std::to_string(raw.node_lines[by_tag[i - 1]]) + ")");
    const std::size_t tet_count = raw.tet_lines.size();
    if (tet_count == 0) fail_at(path, last_line, "the file holds no tetrahedra (element type 4 or 11)");
    if (tet_count > UINT32_MAX) fail_at(path, last_line, "more than 2^32-1 tetrahedra");
    std::vector<uint64_t> sorted_tags(node_count);
    for (std::size_t i = 0; i < node_count; ++i) sorted_tags[i] = raw.node_tags[by_tag[i]];

    // Tet nodes as ranks in the sorted order; mark the ranks in use.
    const std::size_t per_tet = raw.nodes_per_tet;
    std::vector<std::size_t> node_rank(per_tet * tet_count);
    std::vector<unsigned char> used(node_count, 0);
    for (std::size_t t = 0; t < tet_count; ++t) {
        for (std::size_t i = 0; i < per_tet; ++i) {
            const uint64_t tag = raw.tet_tags[per_tet * t + i];
            const auto it = std::lower_bound(sorted_tags.begin(), sorted_tags.end(), tag);
            if (it == sorted_tags.end() || *it != tag)
                fail_at(path, raw.tet_lines[t], "unknown node tag " + std::to_string(tag));
            for (std::size_t j = 0; j < i; ++j)
                if (raw.tet_tags[per_tet * t + j] == tag)
                    fail_at(path, raw.tet_lines[t],
                            "the tetrahedron repeats node tag " + std::to_string(tag));
            const std::size_t rank = std::size_t(it - sorted_tags.begin());
            node_rank[per_tet * t + i] = rank;
            used[rank] = 1;
        }
    }

    TetMesh mesh;
    mesh.nodes_per_tet = raw.nodes_per_tet;
    std::vector<uint32_t> dense(node_count, 0);
    std::size_t kept = 0;
    for (std::size_t rank = 0; rank < node_count; ++rank) {
        if (!used[rank]) continue;  // unused nodes are dropped
        if (kept == UINT32_MAX) fail_at(path, last_line, "more than 2^32-1 nodes in use");
        dense[rank] = uint32_t(kept++);
        const double* p = &raw.node_positions[3 * by_tag[rank]];
        mesh.positions.insert(mesh.positions.end(), p, p + 3);
    }
    // Gmsh's type 11 lists the mid-edge nodes of edges (2,3) and (1,3) as 8 and 9, the other
    // way round from common/quadratic_tet_nodes.h.
    static constexpr int kFromGmsh[kQuadraticTetNodes] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
    static constexpr int kNegative[4] = {0, 1, 3, 2};
    mesh.tets.resize(per_tet * tet_count);
    for (std::size_t t = 0; t < tet_count; ++t) {
        uint32_t* tet = &mesh.tets[per_tet * t];
        for (std::size_t i = 0; i < per_tet; ++i)
            tet[i] = dense[node_rank[per_tet * t + (per_tet == kQuadraticTetNodes ? kFromGmsh[i] : i)]];
        const double* x[4];
        for (int i = 0; i < 4; ++i) x[i] = &mesh.positions[3 * std::size_t(tet[i])];
        const double six_vol = tet_geometry::six_volume(x[0], x[1], x[2], x[3]);
        if (tet_geometry::is_flat(six_vol, tet_geometry::longest_edge(x[0], x[1], x[2], x[3])))
            fail_at(path, raw.tet_lines[t], "the tetrahedron has zero volume");
        if (six_vol < 0.0) permute_corners(tet, mesh.nodes_per_tet, kNegative);  // negatively oriented: reorder
    }
    return mesh;
}

// Skips an unknown section (e.g. $PhysicalNames, $Entities, $Periodic) up to its end marker.
void skip_section(LineReader& r, std::string_view name) {
    const std::string section = "$" + std::string(name);
    const std::string end = "$End" + std::string(name);
    while (true) {
        r.next_in(section.c_str());
        if (r.tokens()[0] == end) return;
    }
}

}  // namespace

TetMesh read_gmsh(const std::string& path) {
    std::ifstream in(path, std::ios::in | std::ios::binary);
    if (!in) throw Error(Status::io_error, path + ": cannot open: " + std::strerror(errno));
    LineReader r(in, path);

    RawMesh raw;
    int version = 0;  // 2 or 4 once $MeshFormat is read
    bool have_nodes = false, have_elements = false;
    while (r.next()) {
        const std::string_view marker = r.tokens()[0];
        if (marker.size() < 2 || marker[0] != '$')
            r.fail("expected a section start such as $Nodes, found '" + r.excerpt(0) + "'");
        r.expect_alone();
        const std::string_view name = marker.substr(1);
        if (name == "MeshFormat") {
            if (version != 0) r.fail("second $MeshFormat section");
            r.next_in("$MeshFormat");
            if (r.tokens().size() < 3)
                r.expect_token_count(3, "the format line (version file_type data_size)");
            const double number = r.real_at(0, "version");
            const int64_t file_type = r.integer_at(1, "file type");
            r.integer_at(2, "data size");
            if (file_type != 0) r.fail("binary .msh files are not supported (save as ASCII)");
            if (number == 2.2)
                version = 2;
            else if (number == 4.1)
                version = 4;
            else
                r.fail("unsupported .msh version " + r.excerpt(0) + " (2.2 and 4.1 are read)");
            r.next_in("$MeshFormat");
            r.expect_marker("$EndMeshFormat");
        } else if (name == "Nodes" || name == "Elements") {
            if (version == 0) r.fail("$" + std::string(name) + " before $MeshFormat");
            bool& seen = name == "Nodes" ? have_nodes : have_elements;
            if (seen) r.fail("second $" + std::string(name) + " section");
            seen = true;
            if (name == "Nodes")
                version == 2 ? read_nodes_v2(r, raw) : read_nodes_v4(r, raw);
            else
                version == 2 ? read_elements_v2(r, raw) : read_elements_v4(r, raw);
        } else if (name.substr(0, 3) == "End") {
            r.fail("'" + r.excerpt(0) + "' without a matching section start");
        } else {
            skip_section(r, name);
        }
    }
    if (version == 0) r.fail("no $MeshFormat section: not a Gmsh .msh file");
    if (!have_nodes) r.fail("no $Nodes section");
    return resolve(raw, path, r.line_number());
}

}  // namespace lfem
