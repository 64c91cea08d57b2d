#include "octree/octomap_io.hpp"

#include "base/error.hpp"
#include "octree/octree_view.hpp"

#include "octree/bounded_tree.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace octoprox {
namespace {

constexpr const char *kBinaryHeader = "# Octomap OcTree binary file";
constexpr const char *kFullHeader = "# Octomap OcTree file";
constexpr size_t kMaxHeaderLines = 64;

struct Header {
    MapFormat format = MapFormat::kBinary;
    std::string id;
    double resolution = 0.0;
    bool has_resolution = false;
    long long size = -1;
    size_t body_offset = 0;
};

// A string stream swallows std::bad_alloc and sets badbit, which would then
// read as a short or corrupt map; with badbit in its exception mask the
// stream rethrows the original exception, and the caller reports it as
// out of memory.  (End of input sets eofbit and failbit, never badbit.)
void rethrow_allocation_failures(std::ios &stream) { stream.exceptions(std::ios::badbit); }

bool starts_with(const std::string &text, const char *prefix) {
    return text.compare(0, std::strlen(prefix), prefix) == 0;
}

// Reads the text header up to and including the line "data".
Header parse_header(const std::string &bytes) {
    Header header;
    std::istringstream in(bytes);
    rethrow_allocation_failures(in);
    std::string line;
    if (!std::getline(in, line)) throw_corrupt("empty input: no OctoMap header");
    if (starts_with(line, kBinaryHeader)) header.format = MapFormat::kBinary;
    else if (starts_with(line, kFullHeader)) header.format = MapFormat::kFull;
    else throw_corrupt("not an OctoMap file: the first line is not \"# Octomap OcTree [binary] file\"");

    for (size_t lines = 0; lines < kMaxHeaderLines && std::getline(in, line); ++lines) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream fields(line);
        rethrow_allocation_failures(fields);
        std::string token;
        fields >> token;
        if (token.empty() || token[0] == '#') continue;
        if (token == "data") {
            // At the end of the input (no newline after "data") tellg is -1:
            // the body is empty, which only an empty tree may have.
            const std::streamoff offset = in.tellg();
            header.body_offset = offset < 0 ? bytes.size() : static_cast<size_t>(offset);
            if (!header.has_resolution) throw_corrupt("header has no \"res\" line");
            if (header.format == MapFormat::kFull && header.id.empty())
                throw_corrupt("header has no \"id\" line");
            return header;
        }
        if (token == "id") fields >> header.id;
        else if (token == "size") {
            fields >> header.size;
            if (!fields.fail() && header.size < 0) throw_corrupt("header gives a negative node count");
        }
        else if (token == "res") {
            fields >> header.resolution;
            header.has_resolution = true;
        }
        if (fields.fail()) throw_corrupt("malformed header line \"" + line.substr(0, 60) + "\"");
    }
    throw_corrupt("header has no \"data\" line (truncated or not an OctoMap file)");
}

// Checks a node stream of either format: child layout, depth never below
// the finest cells, finite log-odds, no byte missing or left over.
class BodyValidator {
public:
    BodyValidator(const std::string &body, MapFormat format) : body_(body), format_(format) {}

    long long validate() {
        if (body_.empty()) return 0;  // an empty tree has no nodes at all
        count_ = 1;
        if (format_ == MapFormat::kBinary) binary_node(0);
        else full_node(0);
        if (pos_ != body_.size())
            throw_corrupt(format("%zu unexpected bytes after the tree data", body_.size() - pos_));
        return count_;
    }

private:
    const unsigned char *take(size_t n) {
        if (body_.size() - pos_ < n)
            throw_corrupt(format("truncated: tree data ends at byte %zu", body_.size()));
        const auto *at = reinterpret_cast<const unsigned char *>(body_.data()) + pos_;
        pos_ += n;
        return at;
    }

    void binary_node(int depth) {
        const unsigned char *bits = take(2);
        const uint16_t children = static_cast<uint16_t>(bits[0] | (bits[1] << 8));
        for (int i = 0; i < 8; ++i) {
            const int pair = (children >> (2 * i)) & 3;
            if (pair != 0) ++count_;
            if (pair == 3) {
                if (depth + 1 >= kTreeDepth) throw_corrupt("a cell at the finest depth has children");
                binary_node(depth + 1);
            }
        }
    }

    void full_node(int depth) {
        float value;
        std::memcpy(&value, take(sizeof value), sizeof value);
        if (!std::isfinite(value)) throw_corrupt("a node holds a non-finite log-odds value");
        const unsigned char children = *take(1);
        if (children != 0 && depth >= kTreeDepth) throw_corrupt("a cell at the finest depth has children");
        for (int i = 0; i < 8; ++i) {
            if ((children >> i) & 1) {
                ++count_;
                full_node(depth + 1);
            }
        }
    }

    const std::string &body_;
    MapFormat format_;
    size_t pos_ = 0;
    long long count_ = 0;
};

// Other tree types (ColorOcTree, ...) hold other node data.
void require_octree_type(const Header &header) {
    if (header.format == MapFormat::kFull && header.id != "OcTree")
        throw ApiError(OPX_ERROR_UNSUPPORTED,
                       "map type \"" + header.id.substr(0, 40) + "\" is not supported (only OcTree)");
}

void check_resolution(double resolution) {
    if (!resolution_in_range(resolution))
        throw_corrupt(format("resolution %g is outside %g to %g metres", resolution, kMinResolution,
                                   kMaxResolution));
}

}  // namespace

std::unique_ptr<SensorOctree> read_map_body(const std::string &body, MapFormat format,
                                            double resolution, OctreeParams params) {
    check_resolution(resolution);
    BodyValidator(body, format).validate();
    params.resolution = resolution;
    auto tree = std::make_unique<BoundedOcTree>(resolution);
    // Leaves of a .bt file take the clamping bounds as their values.
    tree->setClampingThresMin(params.clamp_min);
    tree->setClampingThresMax(params.clamp_max);
    if (!body.empty()) {
        std::istringstream in(body);
        rethrow_allocation_failures(in);
        if (format == MapFormat::kBinary) tree->readBinaryData(in);
        else tree->readData(in);
    }
    return std::make_unique<SensorOctree>(params, std::move(tree));
}

std::unique_ptr<SensorOctree> read_map_file_bytes(const std::string &bytes, OctreeParams params) {
    const Header header = parse_header(bytes);
    require_octree_type(header);
    check_resolution(header.resolution);
    const std::string body = bytes.substr(header.body_offset);
    const long long nodes = BodyValidator(body, header.format).validate();
    if (header.size >= 0 && header.size != nodes)
        throw_corrupt(format("header says %lld nodes, the data holds %lld", header.size, nodes));
    return read_map_body(body, header.format, header.resolution, params);
}

size_t map_file_size_bound(const std::string &prefix) {
    const Header header = parse_header(prefix);
    require_octree_type(header);  // before its nodes are taken for an OcTree's
    if (header.size < 0) return SIZE_MAX;
    const size_t node_bytes = header.format == MapFormat::kBinary ? 2 : sizeof(float) + 1;
    const auto nodes = static_cast<unsigned long long>(header.size);
    if (nodes > (SIZE_MAX - 1 - header.body_offset) / node_bytes) return SIZE_MAX - 1;  // bounded, if not by memory
    return header.body_offset + node_bytes * static_cast<size_t>(nodes);
}

// The header OctoMap writes, but with the resolution in its shortest exact
// decimal form (OctoMap prints 6 digits, which loses e.g. 0.0123456789).
// The bodies come from OctoMap's node writers; its writeBinaryData would
// also print a debug line to stderr in Debian's build.
std::string write_map_file_bytes(const SensorOctree &tree, MapFormat format) {
    const BoundedOcTree &octree = tree.octomap_tree();
    char resolution[64];
    const auto written = std::to_chars(resolution, resolution + sizeof resolution - 1,
                                       octree.getResolution());
    *written.ptr = '\0';
    std::ostringstream out;
    rethrow_allocation_failures(out);
    out << (format == MapFormat::kBinary ? kBinaryHeader : kFullHeader)
        << "\n# (feel free to add / change comments, but leave the first line as it is!)\n#\n"
        << "id " << octree.getTreeType() << "\nsize " << octree.size() << "\nres " << resolution
        << "\ndata\n";
    if (octree.getRoot() != nullptr) {
        if (format == MapFormat::kBinary) octree.writeBinaryNode(out, octree.getRoot());
        else octree.writeData(out);
    }
    if (!out) throw ApiError(OPX_ERROR_INTERNAL, "failed to serialise the tree");
    return out.str();
}

}  // namespace octoprox
