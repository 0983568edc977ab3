// STL reading and writing. The format is decided from the content: a file is binary when its
// size is exactly 84 + 50 n for the triangle count n in its header, whatever the header says
// (binary headers often start with "solid", e.g. opencamlib's ktoolcav.stl); otherwise it
// must parse as ASCII. Every rejection names the source and the place.
#include "swarf/mesh/stl.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "swarf/core/io.h"

namespace swarf {
namespace {

static_assert(std::endian::native == std::endian::little,
              "binary STL is little-endian; this reader copies floats directly");

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kBinaryPrefixBytes = 84;
constexpr std::size_t kBinaryTriangleBytes = 50;

using Soup = std::vector<std::array<Vec3, 3>>;

std::string str(std::string_view s) {
  return std::string(s);
}

// One triangle as read, with the normal stored in the file (may be zero or junk).
struct ReadTriangle {
  std::array<Vec3, 3> v;
  Vec3 normal;
};

std::optional<std::string> non_finite(const ReadTriangle& t) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(t.v[k].x) || !std::isfinite(t.v[k].y) || !std::isfinite(t.v[k].z))
      return "vertex " + std::to_string(k + 1) + " has a non-finite coordinate (NaN or inf)";
  return std::nullopt;
}

// --- binary -------------------------------------------------------------------------------

std::uint32_t binary_count(std::string_view bytes) {
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + kHeaderBytes, sizeof n);
  return n;
}

bool is_binary(std::string_view bytes) {
  if (bytes.size() < kBinaryPrefixBytes) return false;
  const std::uint64_t n = binary_count(bytes);
  return kBinaryPrefixBytes + kBinaryTriangleBytes * n == bytes.size();
}

Result<std::vector<ReadTriangle>> parse_binary(std::string_view bytes, std::string_view name) {
  const std::uint32_t n = binary_count(bytes);
  std::vector<ReadTriangle> out;
  out.reserve(n);
  const char* p = bytes.data() + kBinaryPrefixBytes;
  for (std::uint32_t i = 0; i < n; ++i, p += kBinaryTriangleBytes) {
    float f[12];
    std::memcpy(f, p, sizeof f);
    ReadTriangle t;
    t.normal = {f[0], f[1], f[2]};
    for (int k = 0; k < 3; ++k)
      t.v[k] = {f[3 + 3 * k], f[4 + 3 * k], f[5 + 3 * k]};
    if (auto why = non_finite(t))
      return bad_input(str(name) + ": triangle " + std::to_string(i + 1) + ": " + *why);
    out.push_back(t);
  }
  return out;
}

// --- ASCII --------------------------------------------------------------------------------

// Whitespace-separated tokens with their line numbers.
class Tokenizer {
 public:
  explicit Tokenizer(std::string_view text) : text_(text) {}

  /// The next token, or empty at the end of the input.
  std::string_view next() {
    skip_space();
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]))
      ++pos_;
    token_line_ = line_;
    return text_.substr(begin, pos_ - begin);
  }
  /// The rest of the current line (the name after "solid"), consumed.
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n')
      ++pos_;
  }
  /// Line of the last token returned (1-based); the last line at the end of the input.
  std::size_t line() const { return token_line_; }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
  }
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t token_line_ = 1;
};

bool keyword_is(std::string_view token, std::string_view keyword) {
  // Keywords are lower case by the format; some exporters write upper case.
  return token.size() == keyword.size() &&
         std::equal(token.begin(), token.end(), keyword.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

std::string quoted(std::string_view token) {
  if (token.empty()) return "end of file";
  std::string s = "'";
  // Garbage may hold control bytes: show at most 20 printable characters.
  for (std::size_t i = 0; i < token.size() && i < 20; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    s += std::isprint(c) ? static_cast<char>(c) : '?';
  }
  if (token.size() > 20) s += "...";
  return s + "'";
}

bool parse_number(std::string_view token, double& value) {
  if (token.empty()) return false;
  if (token.front() == '+') token.remove_prefix(1);  // from_chars refuses a leading '+'
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

class AsciiParser {
 public:
  AsciiParser(std::string_view text, std::string_view name) : tok_(text), name_(name) {}

  Result<std::vector<ReadTriangle>> parse() {
    std::string_view t = tok_.next();
    if (!keyword_is(t, "solid")) return fail("expected 'solid', found " + quoted(t));
    tok_.skip_line();
    std::vector<ReadTriangle> out;
    for (;;) {
      t = tok_.next();
      if (keyword_is(t, "endsolid")) {
        tok_.skip_line();
        t = tok_.next();
        if (t.empty()) break;
        // Several solids in one file (some exporters write one per body).
        if (!keyword_is(t, "solid"))
          return fail("expected 'solid' or end of file, found " + quoted(t));
        tok_.skip_line();
        continue;
      }
      if (!keyword_is(t, "facet"))
        return fail("expected 'facet' or 'endsolid', found " + quoted(t));
      ReadTriangle tri;
      SWARF_RETURN_IF_ERROR(expect("normal"));
      SWARF_RETURN_IF_ERROR(vector(tri.normal, /*finite=*/false, out.size()));
      SWARF_RETURN_IF_ERROR(expect("outer"));
      SWARF_RETURN_IF_ERROR(expect("loop"));
      for (int k = 0; k < 3; ++k) {
        SWARF_RETURN_IF_ERROR(expect("vertex"));
        SWARF_RETURN_IF_ERROR(vector(tri.v[k], /*finite=*/true, out.size()));
      }
      SWARF_RETURN_IF_ERROR(expect("endloop"));
      SWARF_RETURN_IF_ERROR(expect("endfacet"));
      out.push_back(tri);
    }
    return out;
  }

 private:
  Status fail(const std::string& what) const {
    return bad_input(str(name_) + ": line " + std::to_string(tok_.line()) + ": " + what);
  }
  Status expect(std::string_view keyword) {
    const std::string_view t = tok_.next();
    if (keyword_is(t, keyword)) return {};
    return fail("expected '" + str(keyword) + "', found " + quoted(t));
  }
  Status vector(Vec3& v, bool finite, std::size_t triangle_index) {
    for (int i = 0; i < 3; ++i) {
      const std::string_view t = tok_.next();
      double x = 0.0;
      if (!parse_number(t, x)) return fail("expected a number, found " + quoted(t));
      if (finite && !std::isfinite(x))
        return bad_input(str(name_) + ": line " + std::to_string(tok_.line()) + ": triangle " +
                         std::to_string(triangle_index + 1) + ": non-finite coordinate " +
                         quoted(t));
      v[i] = x;
    }
    return {};
  }

  Tokenizer tok_;
  std::string_view name_;
};

bool starts_with_solid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i])))
    ++i;
  return keyword_is(bytes.substr(i, 5), "solid");
}

// True when the first bytes hold characters no ASCII STL has (NUL and most control bytes).
bool looks_binary(std::string_view bytes) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 512);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c < 9 || (c > 13 && c < 32) || c == 127) return true;
  }
  return false;
}

Status binary_size_error(std::string_view bytes, std::string_view name) {
  const std::uint64_t n = binary_count(bytes);
  const std::uint64_t expected = kBinaryPrefixBytes + kBinaryTriangleBytes * n;
  std::string why =
      expected > bytes.size() ? "truncated binary STL" : "binary STL with extra bytes";
  return bad_input(str(name) + ": " + why + ": the header counts " + std::to_string(n) +
                   " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                   std::to_string(bytes.size()) + " bytes");
}

// --- writing ------------------------------------------------------------------------------

Vec3 facet_normal(const Mesh& mesh, std::size_t t) {
  const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
  return normalized(cross(b - a, c - a));
}

void append_number(std::string& s, double v) {
  char buf[32];
  // Shortest text that reads back to the same double.
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, ec == std::errc() ? end : buf);
}

void append_vector(std::string& s, Vec3 v) {
  append_number(s, v.x);
  s += ' ';
  append_number(s, v.y);
  s += ' ';
  append_number(s, v.z);
  s += '\n';
}

std::string stl_ascii_bytes(const Mesh& mesh) {
  std::string s = "solid swarf\n";
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    s += "  facet normal ";
    append_vector(s, facet_normal(mesh, t));
    s += "    outer loop\n";
    for (int k = 0; k < 3; ++k) {
      s += "      vertex ";
      append_vector(s, mesh.corner(t, k));
    }
    s += "    endloop\n  endfacet\n";
  }
  s += "endsolid swarf\n";
  return s;
}

}  // namespace

Result<StlFile> parse_stl(std::string_view bytes, std::string_view source_name) {
  const std::string_view name = source_name.empty() ? std::string_view("STL") : source_name;
  if (bytes.empty()) return bad_input(str(name) + ": empty file");
  StlFile file;
  std::vector<ReadTriangle> tris;
  if (is_binary(bytes)) {
    auto r = parse_binary(bytes, name);
    if (!r.ok()) return r.status();
    tris = std::move(*r);
    file.binary = true;
  } else if (starts_with_solid(bytes) && !(looks_binary(bytes) && bytes.size() >= 84)) {
    auto r = AsciiParser(bytes, name).parse();
    if (!r.ok()) return r.status();
    tris = std::move(*r);
  } else if (bytes.size() >= kBinaryPrefixBytes && looks_binary(bytes)) {
    return binary_size_error(bytes, name);
  } else if (bytes.size() >= kBinaryPrefixBytes) {
    return bad_input(str(name) + ": not an STL file: text that does not start with 'solid', and " +
                     std::to_string(bytes.size()) + " bytes do not fit the binary layout");
  } else {
    return bad_input(str(name) + ": not an STL file (" + std::to_string(bytes.size()) +
                     " bytes: too short for binary STL and not starting with 'solid')");
  }
  if (tris.empty()) return bad_input(str(name) + ": no triangles (empty mesh)");

  Soup soup;
  soup.reserve(tris.size());
  std::size_t flipped_normals = 0;
  for (const ReadTriangle& t : tris) {
    soup.push_back(t.v);
    // A stored normal that points against the winding: the file's two orientation records
    // disagree. Zero normals (many exporters write them) say nothing.
    const Vec3 w = cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
    if (std::isfinite(norm_sq(t.normal)) && dot(w, t.normal) < 0.0) ++flipped_normals;
  }
  file.mesh = weld(soup);
  file.check = check_mesh(file.mesh);
  const MeshCheck& c = file.check;
  const std::string n = str(name);
  if (c.open_edges > 0)
    file.warnings.push_back(n + ": " + std::to_string(c.open_edges) +
                            " open edges (used by one triangle): the mesh is not closed");
  if (c.non_manifold_edges > 0)
    file.warnings.push_back(n + ": " + std::to_string(c.non_manifold_edges) +
                            " non-manifold edges (used by more than two triangles)");
  if (c.inconsistent_edges > 0)
    file.warnings.push_back(n + ": " + std::to_string(c.inconsistent_edges) +
                            " edges whose triangles disagree in orientation");
  if (c.degenerate_triangles > 0)
    file.warnings.push_back(n + ": " + std::to_string(c.degenerate_triangles) +
                            " degenerate triangles (zero area)");
  if (flipped_normals > 0)
    file.warnings.push_back(n + ": " + std::to_string(flipped_normals) +
                            " stored normals point against the vertex winding");
  if (c.closed() && c.inconsistent_edges == 0 && c.volume_mm3 < 0.0)
    file.warnings.push_back(n + ": negative volume: the triangles face inwards");
  return file;
}

Result<StlFile> read_stl(const std::string& path) {
  Result<std::string> bytes = read_file(path);
  if (!bytes.ok()) return bytes.status();
  return parse_stl(*bytes, path);
}

std::string stl_binary_bytes(const Mesh& mesh) {
  std::string s(kHeaderBytes, ' ');
  // Never "solid" at the start, so that naive readers do not take it for ASCII.
  const std::string_view header = "binary STL written by swarf";
  std::copy(header.begin(), header.end(), s.begin());
  const std::uint32_t n = static_cast<std::uint32_t>(mesh.size());
  s.append(reinterpret_cast<const char*>(&n), sizeof n);
  s.reserve(kBinaryPrefixBytes + kBinaryTriangleBytes * mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const Vec3 nv = facet_normal(mesh, t);
    float f[12] = {static_cast<float>(nv.x), static_cast<float>(nv.y), static_cast<float>(nv.z)};
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.corner(t, k);
      f[3 + 3 * k] = static_cast<float>(p.x);
      f[4 + 3 * k] = static_cast<float>(p.y);
      f[5 + 3 * k] = static_cast<float>(p.z);
    }
    s.append(reinterpret_cast<const char*>(f), sizeof f);
    s.append(2, '\0');  // attribute byte count
  }
  return s;
}

Status write_stl(const std::string& path, const Mesh& mesh, bool binary) {
  if (mesh.empty()) return bad_input(path + ": refusing to write an empty mesh");
  return write_file_atomic(path, binary ? stl_binary_bytes(mesh) : stl_ascii_bytes(mesh));
}

}  // namespace swarf
