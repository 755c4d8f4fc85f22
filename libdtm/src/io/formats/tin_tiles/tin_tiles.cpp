// SPDX-License-Identifier: MIT
// The tiled TIN's manifest and its reading in one process (dtm/io/formats/tin_tiles.hpp). The
// manifest is parsed with GDAL's JSON classes (cpl_json.h); the tiles are dtm PLYs read by
// read_tin_tiles' caller's reader (ply_reader.cpp) with their vertex_id element. Putting them
// together: each tile's vertices go to their numbers (a vertex named by triangles of two tiles
// is in both, and both must hold the same coordinates), its faces fill the face-number runs the
// manifest gives, its constrained edges are renumbered and all are sorted by (a, b), as the
// single-machine TIN lists them (finish_tin).
#include "dtm/io/formats/tin_tiles.hpp"

#include <cpl_error.h>
#include <cpl_json.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/json_writer.hpp"
#include "io/formats/tin_checks.hpp"

namespace dtm::io {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view format_name = "dtm-tin-tiles";

[[noreturn]] void bad(const fs::path& path, const std::string& what) {
    throw InputError(path, 0, 0, "not a valid tiled TIN manifest: " + what);
}

std::uint64_t count_of(const fs::path& path, const CPLJSONObject& object, const std::string& key) {
    const CPLJSONObject value = object.GetObj(key);
    if (!value.IsValid() || (value.GetType() != CPLJSONObject::Type::Integer &&
                             value.GetType() != CPLJSONObject::Type::Long)) {
        bad(path, "'" + key + "' is missing or not an integer");
    }
    const GInt64 n = value.ToLong();
    if (n < 0) bad(path, "'" + key + "' is negative");
    return static_cast<std::uint64_t>(n);
}

bool same_bits(const Point3& a, const Point3& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

}  // namespace

std::string tin_manifest_json(const TinTilesManifest& m) {
    JsonWriter json;
    json.begin_object();
    json.value("format", format_name);
    json.value("version", std::size_t{1});
    json.value("crs", m.crs_wkt);
    json.value("vertices", std::size_t{m.vertices});
    json.value("faces", std::size_t{m.faces});
    json.value("constrained_edges", std::size_t{m.edges});
    json.begin_array("tiles");
    for (const TinTile& t : m.tiles) {
        json.begin_object();
        json.value("file", t.file);
        json.value("vertices", std::size_t{t.vertices});
        json.value("faces", std::size_t{t.faces});
        json.value("constrained_edges", std::size_t{t.edges});
        json.begin_array("extent", JsonWriter::Layout::inline_);
        for (const double v : t.extent) json.value({}, v);
        json.end();
        json.begin_array("face_runs", JsonWriter::Layout::inline_);
        for (const auto& [first, count] : t.face_runs) {
            json.begin_array({}, JsonWriter::Layout::inline_);
            json.value({}, std::size_t{first});
            json.value({}, std::size_t{count});
            json.end();
        }
        json.end();
        json.end();
    }
    json.end();
    json.end();
    return json.str();
}

TinTilesManifest parse_tin_manifest(const fs::path& path, std::string_view text) {
    CPLJSONDocument document;
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool loaded = document.LoadMemory(std::string(text));
    const std::string why = CPLGetLastErrorMsg();
    CPLPopErrorHandler();
    if (!loaded) bad(path, "the file is not JSON (" + why + ")");
    const CPLJSONObject root = document.GetRoot();
    if (root.GetString("format") != format_name) {
        bad(path, "its \"format\" is not \"" + std::string(format_name) + "\"");
    }
    if (root.GetInteger("version") != 1) bad(path, "dtm reads version 1 only");
    TinTilesManifest m;
    m.crs_wkt = root.GetString("crs");
    m.vertices = count_of(path, root, "vertices");
    m.faces = count_of(path, root, "faces");
    m.edges = count_of(path, root, "constrained_edges");
    const CPLJSONArray tiles = root.GetArray("tiles");
    if (!tiles.IsValid() || tiles.Size() == 0) bad(path, "'tiles' is missing or empty");
    for (int i = 0; i < tiles.Size(); ++i) {
        const CPLJSONObject t = tiles[i];
        TinTile tile;
        tile.file = t.GetString("file");
        if (tile.file.empty() || tile.file.find('/') != std::string::npos) {
            bad(path, "tile " + std::to_string(i) + " has no file name in the manifest's folder");
        }
        tile.vertices = count_of(path, t, "vertices");
        tile.faces = count_of(path, t, "faces");
        tile.edges = count_of(path, t, "constrained_edges");
        const CPLJSONArray extent = t.GetArray("extent");
        if (extent.IsValid() && extent.Size() == 4) {
            for (int k = 0; k < 4; ++k)
                tile.extent[static_cast<std::size_t>(k)] = extent[k].ToDouble();
        }
        const CPLJSONArray runs = t.GetArray("face_runs");
        std::uint64_t covered = 0;
        for (int r = 0; runs.IsValid() && r < runs.Size(); ++r) {
            const CPLJSONArray run = runs[r].ToArray();
            if (!run.IsValid() || run.Size() != 2 || run[0].ToLong(-1) < 0 ||
                run[1].ToLong(-1) < 0) {
                bad(path, "tile " + std::to_string(i) + ": face run " + std::to_string(r) +
                              " is not [first, count]");
            }
            tile.face_runs.push_back({static_cast<std::uint64_t>(run[0].ToLong()),
                                      static_cast<std::uint64_t>(run[1].ToLong())});
            covered += tile.face_runs.back()[1];
        }
        if (covered != tile.faces) {
            bad(path, "tile " + std::to_string(i) + ": its face runs cover " +
                          std::to_string(covered) + " faces, not " + std::to_string(tile.faces));
        }
        m.tiles.push_back(std::move(tile));
    }
    return m;
}

std::vector<std::string> tin_manifest_tiles(const fs::path& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) return {};
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
        std::vector<std::string> files;
        for (const TinTile& t : parse_tin_manifest(path, text.str()).tiles) files.push_back(t.file);
        return files;
    } catch (const InputError&) {
        return {};
    }
}

std::string tin_tile_name(const fs::path& manifest, std::string_view token, int rank, int ranks) {
    return manifest.stem().string() + "." + std::string(token) + "." + std::to_string(rank + 1) +
           "-of-" + std::to_string(ranks) + ".ply";
}

std::string new_tile_token() {
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    const auto mixed = static_cast<std::uint64_t>(
                           std::chrono::duration_cast<std::chrono::microseconds>(now).count()) ^
                       (static_cast<std::uint64_t>(::getpid()) << 40);
    char text[17];
    std::snprintf(text, sizeof text, "%08x", static_cast<unsigned>(mixed ^ (mixed >> 32)));
    return text;
}

void commit_tin_manifest(const fs::path& path, const TinTilesManifest& manifest) {
    const std::vector<std::string> old = tin_manifest_tiles(path);
    AtomicOutput file(path);
    {
        std::ofstream out(file.temp_path(), std::ios::binary);
        out << tin_manifest_json(manifest);
        out.close();
        if (!out) throw Error("cannot write " + path.string());
    }
    file.commit();
    for (const std::string& name : old) {
        const bool kept = std::any_of(manifest.tiles.begin(), manifest.tiles.end(),
                                      [&](const TinTile& t) { return t.file == name; });
        std::error_code ignored;
        if (!kept) fs::remove(path.parent_path() / name, ignored);
    }
}

void write_tin_tiles(const Tin& tin, const fs::path& path, const TinWriteOptions& options) {
    TinTilesManifest m;
    m.crs_wkt = options.crs_wkt;
    m.vertices = tin.vertices.size();
    m.faces = tin.triangles.size();
    m.edges = tin.constraints.size();
    TinTile& tile = m.tiles.emplace_back();
    tile.file = tin_tile_name(path, new_tile_token(), 0, 1);
    tile.vertices = m.vertices;
    tile.faces = m.faces;
    tile.edges = m.edges;
    if (m.faces > 0) tile.face_runs.push_back({0, m.faces});
    tile.extent = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()};
    for (const Point3& p : tin.vertices) {
        tile.extent = {std::min(tile.extent[0], p.x), std::min(tile.extent[1], p.y),
                       std::max(tile.extent[2], p.x), std::max(tile.extent[3], p.y)};
    }
    std::vector<std::uint64_t> ids(tin.vertices.size());
    std::iota(ids.begin(), ids.end(), std::uint64_t{0});
    TinWriteOptions tile_options = options;
    tile_options.vertex_ids = ids;
    const fs::path tile_path = path.parent_path() / tile.file;
    AtomicOutput out(tile_path);
    write_tin_ply(tin, out.temp_path(), tile_options);
    out.commit();
    try {
        commit_tin_manifest(path, m);
    } catch (const Error&) {
        std::error_code ignored;
        fs::remove(tile_path, ignored);
        throw;
    }
}

LoadedTin read_tin_tiles(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, 0, "cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    const TinTilesManifest m = parse_tin_manifest(path, text.str());
    constexpr auto max_index = static_cast<std::uint64_t>(std::numeric_limits<VertexIndex>::max());
    if (m.vertices >= max_index || m.faces >= max_index) {
        throw InputError(path, 0, 0,
                         std::to_string(m.vertices) + " vertices and " + std::to_string(m.faces) +
                             " faces: more than one process indexes (2^32 - 1); this tiled TIN "
                             "is read tile by tile only");
    }
    LoadedTin out;
    out.crs_wkt = m.crs_wkt;
    out.tin.vertices.resize(m.vertices);
    out.tin.triangles.resize(m.faces);
    std::vector<std::uint8_t> have(m.vertices, 0);
    std::vector<std::uint8_t> face_set(m.faces, 0);
    for (const TinTile& t : m.tiles) {
        const fs::path file = path.parent_path() / t.file;
        if (!fs::exists(file)) {
            throw InputError(path, 0, 0, "tile " + t.file + " is missing (the manifest lists it)");
        }
        LoadedTin tile = read_tin_ply(file);
        const auto fail = [&](const std::string& what) { throw InputError(file, 0, 0, what); };
        if (tile.vertex_ids.size() != tile.tin.vertices.size()) {
            fail("a tile of a tiled TIN has a vertex_id element with every vertex's number");
        }
        if (tile.tin.triangles.size() != t.faces || tile.tin.constraints.size() != t.edges) {
            fail("its faces or constrained edges are not the manifest's " +
                 std::to_string(t.faces) + " and " + std::to_string(t.edges));
        }
        for (std::size_t i = 0; i < tile.vertex_ids.size(); ++i) {
            const std::uint64_t id = tile.vertex_ids[i];
            if (id >= m.vertices) {
                fail("vertex " + std::to_string(i) + " has number " + std::to_string(id) +
                     " but the TIN has " + std::to_string(m.vertices) + " vertices");
            }
            if (have[id] != 0 && !same_bits(out.tin.vertices[id], tile.tin.vertices[i])) {
                fail("vertex " + std::to_string(id) + " differs from another tile's copy");
            }
            out.tin.vertices[id] = tile.tin.vertices[i];
            have[id] = 1;
        }
        const auto global = [&](VertexIndex v) {
            return static_cast<VertexIndex>(tile.vertex_ids[v]);
        };
        std::size_t next = 0;
        for (const auto& [first, count] : t.face_runs) {
            if (first + count > m.faces)
                fail("a face run passes the TIN's " + std::to_string(m.faces) + " faces");
            for (std::uint64_t f = first; f < first + count; ++f, ++next) {
                if (face_set[f] != 0) fail("face " + std::to_string(f) + " is in two tiles");
                face_set[f] = 1;
                Triangle& to = out.tin.triangles[f];
                for (unsigned k = 0; k < 3; ++k) to.v[k] = global(tile.tin.triangles[next].v[k]);
            }
        }
        for (const ConstrainedEdge& e : tile.tin.constraints) {
            out.tin.constraints.push_back({global(e.a), global(e.b), e.kind});
        }
    }
    if (const auto v = std::find(have.begin(), have.end(), 0); v != have.end()) {
        throw InputError(path, 0, 0,
                         "vertex " + std::to_string(v - have.begin()) + " is in no tile");
    }
    if (const auto f = std::find(face_set.begin(), face_set.end(), 0); f != face_set.end()) {
        throw InputError(path, 0, 0,
                         "face " + std::to_string(f - face_set.begin()) + " is in no tile");
    }
    if (out.tin.constraints.size() != m.edges) {
        throw InputError(path, 0, 0,
                         "the tiles hold " + std::to_string(out.tin.constraints.size()) +
                             " constrained edges, the manifest says " + std::to_string(m.edges));
    }
    std::sort(out.tin.constraints.begin(), out.tin.constraints.end(),
              [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
                  return x.a < y.a || (x.a == y.a && x.b < y.b);
              });
    try {
        link_neighbours(out.tin);
        detail::check_tin_from_file(out.tin);
    } catch (const InputError& e) {
        throw InputError(path, 0, 0, e.what());
    }
    return out;
}

bool is_tin_manifest(const FileHead& head) {
    const std::string_view start = head.bytes.substr(0, 256);
    return start.find('{') != std::string_view::npos &&
           start.find("\"" + std::string(format_name) + "\"") != std::string_view::npos;
}

ReadResult read_tin_tiles_input(const InputFile& file,
                                const ReadOptions&,
                                const Progress& progress) {
    return detail::read_tin_input(file, progress, "dtm tiled TIN", &read_tin_tiles);
}

}  // namespace dtm::io
