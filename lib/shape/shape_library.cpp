/* ----------------------------------------------------------------------
   NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
   spheropolyhedra coupled to elastic wires.

   Copyright (2026) the NSCD package developers. This software is
   distributed under the GNU General Public License, version 2, the
   licence of LAMMPS. See the LICENSE file in the top-level directory
   of the package.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: the NSCD package developers
------------------------------------------------------------------------- */

#include "shape/shape_library.h"

#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

namespace nscd {
namespace {

constexpr int kMaxVerticesPerShape = 1000000;
// Tokens quoted in messages are cut to this many characters (a binary file can hold
// megabyte-long "words").
constexpr size_t kMaxQuotedLength = 60;

// A token as shown in a message: in quotes, control bytes as \xNN (a NUL would cut the
// message short), cut if very long.
std::string in_quotes(const std::string &token)
{
  std::string shown = "'";
  char escaped[8];
  for (size_t i = 0; i < token.size() && i < kMaxQuotedLength; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c < ' ' || c == 0x7f) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      shown += escaped;
    } else {
      shown += token[i];
    }
  }
  if (token.size() <= kMaxQuotedLength) return shown + "'";
  return shown + "...' (" + std::to_string(token.size()) + " characters)";
}

// A name is one word (the text format splits at white space and '#'); control bytes
// would also cut or garble messages.
bool is_valid_name(const std::string &name)
{
  for (unsigned char c : name)
    if (c <= ' ' || c == 0x7f || c == '#') return false;
  return true;
}

// First byte of the line that has no place in a text file: control characters other
// than the white space tab, vertical tab, form feed and carriage return. npos if none.
size_t first_control_byte(const std::string &line)
{
  for (size_t i = 0; i < line.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(line[i]);
    const bool white = c == '\t' || c == '\v' || c == '\f' || c == '\r';
    if ((c < ' ' && !white) || c == 0x7f) return i;
  }
  return std::string::npos;
}

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
      check_plain_text(line);
      const auto tokens = tokens_of(line);
      if (!tokens.empty()) handle(tokens);
    }
    if (in.bad()) fail("reading failed after this line; check that the file is readable and complete");
    if (in_block_) {
      fail_at(block_.line, "shape " + in_quotes(block_.name) + " is not terminated; add a line 'end' after its " +
                               "vertices");
    }
    if (parsed_.empty()) {
      fail_at(std::max(line_number_, 1), "no shape found (empty library); the format is in "
                                         "doc/Howto_nscd_shape_library_format.rst");
    }
    return parsed_;
  }

 private:
  [[noreturn]] void fail_at(int line, const std::string &message) const
  {
    throw ShapeError(source_ + ":" + std::to_string(line) + ": " + message);
  }
  [[noreturn]] void fail(const std::string &message) const { fail_at(line_number_, message); }

  void check_plain_text(const std::string &line) const
  {
    const size_t at = first_control_byte(line);
    if (at == std::string::npos) return;
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(line[at]));
    fail("column " + std::to_string(at + 1) + " holds the control byte " + byte +
         "; a shape library is plain text");
  }

  bool expecting_vertices() const
  {
    return in_block_ && block_.declared_vertices > static_cast<int>(block_.points.size());
  }

  void handle(const std::vector<std::string> &tokens)
  {
    if (expecting_vertices()) {
      if (is_keyword(tokens[0])) {
        fail("shape " + in_quotes(block_.name) + " declares " + std::to_string(block_.declared_vertices) +
             " vertices but " + in_quotes(tokens[0]) + " came after " + std::to_string(block_.points.size()) +
             "; correct the count or the lines 'x y z'");
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
      fail("shape " + in_quotes(block_.name) + " has more vertex lines than the " +
           std::to_string(block_.declared_vertices) + " declared; correct the count in 'vertices N'");
    }
    fail("unknown keyword " + in_quotes(keyword) + "; expected shape, radius, vertices or end ('#' starts a comment)");
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
    const double value = std::strtod(begin, &end);
    if (end == begin || *end != '\0') {
      fail(std::string(what) + " " + in_quotes(token) + " is not a number; write a decimal number such as 0.25 or 1e-3");
    }
    // Overflow gives inf. (Underflow, which also sets ERANGE, gives a tiny or zero value:
    // fine for a coordinate or radius.)
    if (!std::isfinite(value)) {
      fail(std::string(what) + " " + in_quotes(token) + " is not finite; give a finite number");
    }
    return value;
  }

  void start_block(const std::vector<std::string> &tokens)
  {
    if (in_block_) {
      fail("'shape' inside shape " + in_quotes(block_.name) + " (line " + std::to_string(block_.line) +
           "); close each block with 'end' first");
    }
    if (tokens.size() > 2) fail("a shape name is one word, found " + in_quotes(tokens[1] + " " + tokens[2]) + "...; remove the spaces");
    block_ = Block();
    block_.name = tokens.size() == 2 ? tokens[1] : "";
    block_.line = line_number_;
    if (!block_.name.empty()) check_unique_name(block_.name);
    in_block_ = true;
  }

  void check_unique_name(const std::string &name) const
  {
    const int earlier_in_file = parsed_.find(name);
    const int taken = earlier_in_file != 0 ? existing_.size() + earlier_in_file : existing_.find(name);
    if (taken != 0) {
      fail("shape name " + in_quotes(name) + " is already used by shape id " + std::to_string(taken) +
           "; give every shape a different name");
    }
  }

  void read_radius(const std::string &token)
  {
    if (block_.has_radius) fail("second 'radius' in shape " + in_quotes(block_.name) + "; give the radius once");
    const double r = number(token, "radius");
    if (r < 0) fail("radius " + token + " is negative; give a rounding radius >= 0");
    block_.radius = r;
    block_.has_radius = true;
  }

  void read_vertex_count(const std::string &token)
  {
    if (block_.declared_vertices >= 0) fail("second 'vertices' in shape " + in_quotes(block_.name) + "; give the count once");
    const char *begin = token.c_str();
    char *end = nullptr;
    const long count = std::strtol(begin, &end, 10);
    if (end == begin || *end != '\0' || count < 1 || count > kMaxVerticesPerShape) {
      fail("vertex count " + in_quotes(token) + " is not a whole number from 1 to " + std::to_string(kMaxVerticesPerShape) +
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
    if (tokens.size() != 1) fail("'end' takes no value, found " + in_quotes(tokens[1]) + "; write 'end' alone");
    if (!block_.has_radius) fail("shape " + in_quotes(block_.name) + " has no radius; add 'radius R' (R >= 0) before 'end'");
    if (block_.declared_vertices < 0) {
      fail("shape " + in_quotes(block_.name) + " has no vertices; add 'vertices N' and N lines 'x y z' before 'end'");
    }
    try {
      parsed_.add(make_spheropolyhedron(block_.points, block_.radius), block_.name);
    } catch (const ShapeError &e) {
      fail_at(block_.line, "shape " + in_quotes(block_.name) + ": " + e.what());
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

// Reads exactly what Serializer writes and nothing else (lower-case hex, plain decimal
// counts), so that serialize(deserialize(text)) == text for any accepted text.
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
    const bool digits = !w.empty() && w.size() <= 18 && w.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || (w.size() > 1 && w[0] == '0')) damaged(in_quotes(w) + " is not a count or an index");
    const long long v = std::stoll(w);
    if (v < lo || v > hi) damaged("count or index " + w + " is out of range " + std::to_string(lo) + ".." + std::to_string(hi));
    return v;
  }
  // A count of items that take at least `min_chars` characters each: bounded by what is
  // left of the text, so that damaged text cannot make us allocate gigabytes.
  long long count(long long lo, long long hi, size_t min_chars)
  {
    const long long v = integer(lo, hi);
    if (static_cast<unsigned long long>(v) * min_chars > text_.size() - pos_) {
      damaged("it ends too early: count " + std::to_string(v) + " is more than the rest of the text can hold");
    }
    return v;
  }
  double real()
  {
    const std::string w = word();
    if (w.size() != 16 || !is_lower_hex(w)) damaged(in_quotes(w) + " is not a 16-digit hexadecimal number");
    const std::uint64_t bits = std::strtoull(w.c_str(), nullptr, 16);
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
    if (hex.size() % 2 != 0 || !is_lower_hex(hex)) damaged("a name is not an even number of hex digits");
    std::string n;
    for (size_t i = 0; i < hex.size(); i += 2) n += static_cast<char>(std::stoul(hex.substr(i, 2), nullptr, 16));
    return n;
  }
  bool at_end() const { return pos_ == text_.size(); }
  [[noreturn]] static void damaged(const std::string &why)
  {
    throw ShapeError("serialised shape library is damaged: " + why + "; write it again with serialize()");
  }

 private:
  static bool is_lower_hex(const std::string &w) { return w.find_first_not_of("0123456789abcdef") == std::string::npos; }

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

// Fewest characters that one serialised item can take (a real is 16 hex digits and a
// comma, an index at least one digit and a comma): bounds the counts read.
constexpr size_t kRealChars = 17, kIndexChars = 2;
constexpr size_t kVertexChars = 3 * kRealChars;
constexpr size_t kFaceChars = kIndexChars + 3 * kIndexChars + 4 * kRealChars;
constexpr size_t kEdgeChars = 4 * kIndexChars;
constexpr size_t kShapeChars = 1 + 2 * kIndexChars + 13 * kRealChars + kVertexChars;

Spheropolyhedron deserialize_shape(Deserializer &in, std::string *name)
{
  constexpr long long kMax = kMaxVerticesPerShape;
  Spheropolyhedron s;
  *name = in.name();
  s.radius = in.real();
  s.vertices.resize(in.count(1, kMax, kVertexChars));
  const long long last_vertex = static_cast<long long>(s.vertices.size()) - 1;
  for (auto &v : s.vertices) v = in.vec();
  s.faces.resize(in.count(0, 2 * kMax, kFaceChars));
  for (auto &f : s.faces) {
    f.vertices.resize(in.count(3, kMax, kIndexChars));
    for (int &v : f.vertices) v = static_cast<int>(in.integer(0, last_vertex));
    f.normal = in.vec();
    f.offset = in.real();
  }
  const long long last_face = static_cast<long long>(s.faces.size()) - 1;
  const auto edge_count = in.count(0, 3 * kMax, kEdgeChars);
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

// What make_spheropolyhedron guarantees and the rest of the code relies on, checked on a
// shape read from (possibly damaged) serialised text: the counts fit the kind of shape,
// and every number is finite with positive mass properties.
void check_deserialized_shape(const Spheropolyhedron &s)
{
  auto usable = [](double v) { return std::isfinite(v) && v >= DBL_MIN; };
  auto damaged = [](const std::string &why) { Deserializer::damaged("a shape " + why); };
  const long long vertices = static_cast<long long>(s.vertices.size());
  const long long faces = static_cast<long long>(s.faces.size());
  const long long edges = static_cast<long long>(s.edges.size());
  if (vertices <= 2 && (faces != 0 || edges != 0)) damaged("with 1 or 2 vertices has faces or edges");
  if (vertices == 3) damaged("has 3 vertices (neither a spherocylinder nor a polyhedron)");
  if (vertices >= 4 && (faces < 4 || vertices - edges + faces != 2)) damaged("is not a closed polyhedron");
  if (!std::isfinite(s.radius) || s.radius < 0.0 || (vertices <= 2 && s.radius <= 0.0)) damaged("has a bad radius");
  for (const auto &v : s.vertices)
    if (!v.allFinite()) damaged("has a vertex that is not finite");
  for (const auto &f : s.faces)
    if (!f.normal.allFinite() || !std::isfinite(f.offset)) damaged("has a face plane that is not finite");
  for (size_t k = 0; k < s.edges.size(); ++k)
    if (s.edges[k][0] == s.edges[k][1] || s.edge_faces[k][0] == s.edge_faces[k][1]) damaged("has a degenerate edge");
  const Vec3 &inertia = s.principal_inertia;
  if (!usable(s.volume) || !usable(inertia[0]) || !usable(inertia[1]) || !usable(inertia[2]) ||
      !usable(s.bounding_radius)) {
    damaged("has a volume, inertia or bounding radius that is not a finite positive number");
  }
  if (!s.input_centroid.allFinite() || !std::isfinite(s.input_rotation.norm()) ||
      std::abs(s.input_rotation.norm() - 1.0) > 1e-6) {
    damaged("has a non-finite input centroid or a rotation that is not a unit quaternion");
  }
}

void check_room(int size, long long more)
{
  if (size + more > ShapeLibrary::kMaxShapes) {
    throw ShapeError("the shape library would hold " + std::to_string(size + more) + " shapes, more than " +
                     std::to_string(ShapeLibrary::kMaxShapes) +
                     "; use fewer shapes (each shape can be given to any number of grains)");
  }
}

}    // namespace

int ShapeLibrary::add(Spheropolyhedron shape, std::string name)
{
  check_room(size(), 1);
  if (!is_valid_name(name)) {
    throw ShapeError("shape name " + in_quotes(name) + " is not one word; use printable characters without "
                     "spaces or '#'");
  }
  if (!name.empty()) {
    const int taken = find(name);
    if (taken != 0) {
      throw ShapeError("shape name " + in_quotes(name) + " is already used by shape id " + std::to_string(taken) +
                       "; give every shape a different name");
    }
    ids_by_name_.emplace(name, size() + 1);
  }
  shapes_.push_back(std::move(shape));
  names_.push_back(std::move(name));
  return size();
}

void ShapeLibrary::append(const ShapeLibrary &other)
{
  if (&other == this) {    // adding shapes to `other` while reading it would never end
    const ShapeLibrary copy = other;
    return append(copy);
  }
  check_room(size(), other.size());
  for (const auto &name : other.names_) {
    const int taken = name.empty() ? 0 : find(name);
    if (taken != 0) {
      throw ShapeError("shape name " + in_quotes(name) + " is already used by shape id " + std::to_string(taken) +
                       "; rename one of them");
    }
  }
  for (int id = 1; id <= other.size(); ++id) add(other.shapes_[id - 1], other.names_[id - 1]);
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
  const auto it = ids_by_name_.find(name);
  return it == ids_by_name_.end() ? 0 : it->second;
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
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw ShapeError(path + ": is a directory, not a shape library file; give the path of the file");
  }
  std::ifstream in(path);
  if (!in) throw ShapeError(path + ": cannot open the shape library file; check the path and permissions");
  read(in, path);
}

void ShapeLibrary::write(std::ostream &out) const
{
  if (empty()) {
    throw ShapeError("the shape library is empty, so there is nothing to write (reading an empty file "
                     "fails); load or make shapes first");
  }
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
  const auto count = in.count(0, kMaxShapes, kShapeChars);
  ShapeLibrary library;
  for (long long i = 0; i < count; ++i) {
    std::string name;
    Spheropolyhedron s = deserialize_shape(in, &name);
    check_deserialized_shape(s);
    try {
      library.add(std::move(s), std::move(name));
    } catch (const ShapeError &e) {
      Deserializer::damaged(e.what());
    }
  }
  if (!in.at_end()) Deserializer::damaged("there is text after the last shape");
  return library;
}

}    // namespace nscd
