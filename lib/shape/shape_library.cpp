#include "shape/shape_library.h"

#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>

namespace nscd {
namespace {

constexpr int kMaxVerticesPerShape = 1000000;

std::vector<std::string> tokens_of(const std::string &line)
{
  std::istringstream in(line.substr(0, line.find('#')));    // '#' starts a comment
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

bool looks_numeric(const std::string &word)
{
  char *end = nullptr;
  std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

bool is_keyword(const std::string &word)
{
  return word == "shape" || word == "radius" || word == "vertices" || word == "end";
}

// One `shape ... end` block while it is being read.
struct Block {
  std::string name;
  int line = 0;                  // line of the `shape` keyword
  bool has_radius = false;
  double radius = 0.0;
  int declared_vertices = -1;    // from `vertices <n>`, -1 before it
  std::vector<Vec3> points;
};

// Reads the text format line by line; every error names the source and the line.
class LibraryParser {
 public:
  LibraryParser(const std::string &source, const ShapeLibrary &existing) : source_(source), existing_(existing) {}

  ShapeLibrary parse(std::istream &in)
  {
    for (std::string line; std::getline(in, line);) {
      ++line_number_;
      const auto tokens = tokens_of(line);
      if (!tokens.empty()) handle(tokens);
    }
    if (in_block_) {
      fail_at(block_.line, "shape '" + block_.name + "' is not terminated; add a line 'end' after its " +
                               "vertices");
    }
    if (parsed_.empty()) {
      fail_at(std::max(line_number_, 1), "no shape found (empty library); define at least one block "
                                         "'shape NAME' / 'radius R' / 'vertices N' / N lines 'x y z' / 'end'");
    }
    return parsed_;
  }

 private:
  [[noreturn]] void fail_at(int line, const std::string &message) const
  {
    throw ShapeError(source_ + ":" + std::to_string(line) + ": " + message);
  }
  [[noreturn]] void fail(const std::string &message) const { fail_at(line_number_, message); }

  bool expecting_vertices() const
  {
    return in_block_ && block_.declared_vertices > static_cast<int>(block_.points.size());
  }

  void handle(const std::vector<std::string> &tokens)
  {
    if (expecting_vertices()) {
      if (is_keyword(tokens[0])) {
        fail("shape '" + block_.name + "' declares " + std::to_string(block_.declared_vertices) +
             " vertices but '" + tokens[0] + "' came after " + std::to_string(block_.points.size()) +
             "; give exactly that many lines 'x y z' or correct the count");
      }
      read_vertex(tokens);
      return;
    }
    const std::string &keyword = tokens[0];
    if (keyword == "shape") return start_block(tokens);
    if (keyword == "end") return end_block(tokens);
    if (keyword == "radius" || keyword == "vertices") {
      if (!in_block_) fail("'" + keyword + "' outside a shape block; start a block with 'shape NAME'");
      expect_values(tokens, 1);
      return keyword == "radius" ? read_radius(tokens[1]) : read_vertex_count(tokens[1]);
    }
    if (in_block_ && looks_numeric(keyword)) {
      if (block_.declared_vertices < 0) fail("a vertex line before 'vertices N'; declare the count first");
      fail("shape '" + block_.name + "' has more vertex lines than the " +
           std::to_string(block_.declared_vertices) + " declared; correct the count in 'vertices N'");
    }
    fail("unknown keyword '" + keyword + "'; expected shape, radius, vertices or end ('#' starts a comment)");
  }

  void expect_values(const std::vector<std::string> &tokens, size_t count) const
  {
    if (tokens.size() != count + 1) {
      fail("'" + tokens[0] + "' takes " + std::to_string(count) + " value(s), found " +
           std::to_string(tokens.size() - 1) + "; write '" + tokens[0] + (tokens[0] == "radius" ? " R'" : " N'"));
    }
  }

  double number(const std::string &token, const char *what) const
  {
    const char *begin = token.c_str();
    char *end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (end == begin || *end != '\0') {
      fail(std::string(what) + " '" + token + "' is not a number; write a decimal number such as 0.25 or 1e-3");
    }
    if (!std::isfinite(value) || errno == ERANGE) {
      fail(std::string(what) + " '" + token + "' is not finite; give a finite number");
    }
    return value;
  }

  void start_block(const std::vector<std::string> &tokens)
  {
    if (in_block_) {
      fail("'shape' inside shape '" + block_.name + "' (line " + std::to_string(block_.line) +
           "); close each block with 'end' first");
    }
    if (tokens.size() > 2) fail("a shape name is one word, found '" + tokens[1] + " " + tokens[2] + "...'; remove the spaces");
    block_ = Block();
    block_.name = tokens.size() == 2 ? tokens[1] : "";
    block_.line = line_number_;
    if (!block_.name.empty()) check_unique_name(block_.name);
    in_block_ = true;
  }

  void check_unique_name(const std::string &name) const
  {
    if (parsed_.find(name) != 0 || existing_.find(name) != 0) {
      fail("shape name '" + name + "' is already used; give every shape a different name");
    }
  }

  void read_radius(const std::string &token)
  {
    if (block_.has_radius) fail("second 'radius' in shape '" + block_.name + "'; give the radius once");
    const double r = number(token, "radius");
    if (r < 0) fail("radius " + token + " is negative; give a rounding radius >= 0");
    block_.radius = r;
    block_.has_radius = true;
  }

  void read_vertex_count(const std::string &token)
  {
    if (block_.declared_vertices >= 0) fail("second 'vertices' in shape '" + block_.name + "'; give the count once");
    const char *begin = token.c_str();
    char *end = nullptr;
    const long count = std::strtol(begin, &end, 10);
    if (end == begin || *end != '\0' || count < 1 || count > kMaxVerticesPerShape) {
      fail("vertex count '" + token + "' is not a whole number from 1 to " + std::to_string(kMaxVerticesPerShape) +
           "; give the number of 'x y z' lines that follow");
    }
    block_.declared_vertices = static_cast<int>(count);
  }

  void read_vertex(const std::vector<std::string> &tokens)
  {
    if (tokens.size() != 3) {
      fail("a vertex line needs 3 coordinates 'x y z', found " + std::to_string(tokens.size()) +
           " field(s); write one vertex per line");
    }
    block_.points.emplace_back(number(tokens[0], "coordinate"), number(tokens[1], "coordinate"),
                               number(tokens[2], "coordinate"));
  }

  void end_block(const std::vector<std::string> &tokens)
  {
    if (!in_block_) fail("'end' without 'shape'; start a block with 'shape NAME'");
    if (tokens.size() != 1) fail("'end' takes no value, found '" + tokens[1] + "'; write 'end' alone");
    if (!block_.has_radius) fail("shape '" + block_.name + "' has no radius; add 'radius R' (R >= 0) before 'end'");
    if (block_.declared_vertices < 0) {
      fail("shape '" + block_.name + "' has no vertices; add 'vertices N' and N lines 'x y z' before 'end'");
    }
    try {
      parsed_.add(make_spheropolyhedron(block_.points, block_.radius), block_.name);
    } catch (const ShapeError &e) {
      fail_at(block_.line, "shape '" + block_.name + "': " + e.what());
    }
    in_block_ = false;
  }

  std::string source_;
  const ShapeLibrary &existing_;
  int line_number_ = 0;
  bool in_block_ = false;
  Block block_;
  ShapeLibrary parsed_;
};

// --- exact serialisation: ','-separated tokens, doubles as the 16 hex digits of their bits.

constexpr const char *kSerialTag = "nscd-shapes-1";

class Serializer {
 public:
  void word(const std::string &w) { text_ += w + ','; }
  void integer(long long v) { word(std::to_string(v)); }
  void real(double v)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016" PRIx64, bits);
    word(hex);
  }
  void vec(const Vec3 &v)
  {
    for (int k = 0; k < 3; ++k) real(v[k]);
  }
  // Names may hold any byte: stored as hex so the text stays one printable word.
  void name(const std::string &n)
  {
    std::string hex;
    char pair[3];
    for (unsigned char c : n) {
      std::snprintf(pair, sizeof pair, "%02x", c);
      hex += pair;
    }
    word(hex);
  }
  std::string text() const { return text_; }

 private:
  std::string text_;
};

class Deserializer {
 public:
  explicit Deserializer(const std::string &text) : text_(text) {}

  std::string word()
  {
    const auto comma = text_.find(',', pos_);
    if (comma == std::string::npos) damaged("it ends too early");
    std::string w = text_.substr(pos_, comma - pos_);
    pos_ = comma + 1;
    return w;
  }
  long long integer(long long lo, long long hi)
  {
    const std::string w = word();
    char *end = nullptr;
    const long long v = std::strtoll(w.c_str(), &end, 10);
    if (w.empty() || *end != '\0' || v < lo || v > hi) damaged("count or index '" + w + "' is out of range");
    return v;
  }
  double real()
  {
    const std::string w = word();
    char *end = nullptr;
    if (w.size() != 16) damaged("'" + w + "' is not a 16-digit number");
    const std::uint64_t bits = std::strtoull(w.c_str(), &end, 16);
    if (*end != '\0') damaged("'" + w + "' is not a hexadecimal number");
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  Vec3 vec()
  {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = real();
    return v;
  }
  std::string name()
  {
    const std::string hex = word();
    if (hex.size() % 2 != 0) damaged("a name has an odd number of hex digits");
    std::string n;
    for (size_t i = 0; i < hex.size(); i += 2) {
      char *end = nullptr;
      const std::string pair = hex.substr(i, 2);
      n += static_cast<char>(std::strtoul(pair.c_str(), &end, 16));
      if (*end != '\0') damaged("a name holds '" + pair + "', not hex digits");
    }
    return n;
  }
  bool at_end() const { return pos_ == text_.size(); }
  [[noreturn]] static void damaged(const std::string &why)
  {
    throw ShapeError("serialised shape library is damaged: " + why + "; write it again with serialize()");
  }

 private:
  const std::string &text_;
  size_t pos_ = 0;
};

void serialize_shape(Serializer &out, const Spheropolyhedron &s, const std::string &name)
{
  out.name(name);
  out.real(s.radius);
  out.integer(static_cast<long long>(s.vertices.size()));
  for (const auto &v : s.vertices) out.vec(v);
  out.integer(static_cast<long long>(s.faces.size()));
  for (const auto &f : s.faces) {
    out.integer(static_cast<long long>(f.vertices.size()));
    for (int v : f.vertices) out.integer(v);
    out.vec(f.normal);
    out.real(f.offset);
  }
  out.integer(static_cast<long long>(s.edges.size()));
  for (size_t k = 0; k < s.edges.size(); ++k) {
    out.integer(s.edges[k][0]);
    out.integer(s.edges[k][1]);
    out.integer(s.edge_faces[k][0]);
    out.integer(s.edge_faces[k][1]);
  }
  out.real(s.volume);
  out.vec(s.principal_inertia);
  out.real(s.bounding_radius);
  out.vec(s.input_centroid);
  const Quat &q = s.input_rotation;
  for (double c : {q.w(), q.x(), q.y(), q.z()}) out.real(c);
}

Spheropolyhedron deserialize_shape(Deserializer &in, std::string *name)
{
  constexpr long long kMax = kMaxVerticesPerShape;
  Spheropolyhedron s;
  *name = in.name();
  s.radius = in.real();
  s.vertices.resize(in.integer(1, kMax));
  const long long last_vertex = static_cast<long long>(s.vertices.size()) - 1;
  for (auto &v : s.vertices) v = in.vec();
  s.faces.resize(in.integer(0, 2 * kMax));
  for (auto &f : s.faces) {
    f.vertices.resize(in.integer(3, kMax));
    for (int &v : f.vertices) v = static_cast<int>(in.integer(0, last_vertex));
    f.normal = in.vec();
    f.offset = in.real();
  }
  const long long last_face = static_cast<long long>(s.faces.size()) - 1;
  const auto edge_count = in.integer(0, 3 * kMax);
  s.edges.resize(edge_count);
  s.edge_faces.resize(edge_count);
  for (long long k = 0; k < edge_count; ++k) {
    for (int &v : s.edges[k]) v = static_cast<int>(in.integer(0, last_vertex));
    for (int &f : s.edge_faces[k]) f = static_cast<int>(in.integer(0, last_face));
  }
  s.volume = in.real();
  s.principal_inertia = in.vec();
  s.bounding_radius = in.real();
  s.input_centroid = in.vec();
  const double w = in.real(), x = in.real(), y = in.real(), z = in.real();
  s.input_rotation = Quat(w, x, y, z);
  return s;
}

}    // namespace

int ShapeLibrary::add(Spheropolyhedron shape, std::string name)
{
  shapes_.push_back(std::move(shape));
  names_.push_back(std::move(name));
  return size();
}

void ShapeLibrary::append(const ShapeLibrary &other)
{
  shapes_.insert(shapes_.end(), other.shapes_.begin(), other.shapes_.end());
  names_.insert(names_.end(), other.names_.begin(), other.names_.end());
}

const Spheropolyhedron &ShapeLibrary::shape(int id) const
{
  if (id < 1 || id > size()) {
    throw ShapeError("shape id " + std::to_string(id) + " is not in the library (ids 1.." + std::to_string(size()) +
                     "); load more shapes or use an id in range");
  }
  return shapes_[id - 1];
}

const std::string &ShapeLibrary::name(int id) const
{
  shape(id);    // range check
  return names_[id - 1];
}

int ShapeLibrary::find(const std::string &name) const
{
  for (size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return static_cast<int>(i) + 1;
  return 0;
}

double ShapeLibrary::max_bounding_radius() const
{
  double largest = 0.0;
  for (const auto &s : shapes_) largest = std::max(largest, s.bounding_radius);
  return largest;
}

void ShapeLibrary::read(std::istream &in, const std::string &source_name)
{
  LibraryParser parser(source_name, *this);
  append(parser.parse(in));
}

void ShapeLibrary::read_file(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw ShapeError(path + ": cannot open the shape library file; check the path and permissions");
  read(in, path);
}

void ShapeLibrary::write(std::ostream &out) const
{
  out << "# Shape library: " << size() << " shape(s), ids 1.." << size() << " in this order.\n"
      << "# Vertices in each shape's body frame (centre of mass at 0, principal axes).\n";
  char line[128];
  for (int id = 1; id <= size(); ++id) {
    const auto &s = shape(id);
    std::snprintf(line, sizeof line, "# id %d: volume %.10g, principal inertia %.10g %.10g %.10g\n", id, s.volume,
                  s.principal_inertia[0], s.principal_inertia[1], s.principal_inertia[2]);
    out << line << "shape";
    if (!name(id).empty()) out << ' ' << name(id);
    std::snprintf(line, sizeof line, "\nradius %.17g\nvertices %zu\n", s.radius, s.vertices.size());
    out << line;
    for (const auto &v : s.vertices) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", v.x(), v.y(), v.z());
      out << line;
    }
    out << "end\n";
  }
}

std::string ShapeLibrary::serialize() const
{
  Serializer out;
  out.word(kSerialTag);
  out.integer(size());
  for (int id = 1; id <= size(); ++id) serialize_shape(out, shape(id), name(id));
  return out.text();
}

ShapeLibrary ShapeLibrary::deserialize(const std::string &text)
{
  Deserializer in(text);
  if (in.word() != kSerialTag) Deserializer::damaged(std::string("it does not start with '") + kSerialTag + "'");
  const auto count = in.integer(0, std::numeric_limits<int>::max());
  ShapeLibrary library;
  for (long long i = 0; i < count; ++i) {
    std::string name;
    Spheropolyhedron s = deserialize_shape(in, &name);
    library.add(std::move(s), std::move(name));
  }
  if (!in.at_end()) Deserializer::damaged("there is text after the last shape");
  return library;
}

}    // namespace nscd
