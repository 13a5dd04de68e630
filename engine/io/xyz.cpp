#include "engine/io/xyz.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/io/bounded_input.hpp"

namespace aerobreak {

namespace {

// ---- reading ----------------------------------------------------------------------------------

std::vector<std::string_view> split_fields(std::string_view line) {
  constexpr std::string_view whitespace = " \t\r\v\f";
  std::vector<std::string_view> fields;
  std::size_t begin = line.find_first_not_of(whitespace);
  while (begin != std::string_view::npos) {
    const std::size_t end = std::min(line.find_first_of(whitespace, begin), line.size());
    fields.push_back(line.substr(begin, end - begin));
    begin = line.find_first_not_of(whitespace, end);
  }
  return fields;
}

// A whole field as a double (from_chars: locale-independent and correctly rounded, so printed
// shortest representations read back bit-exactly); nullopt if it is not entirely a number.
std::optional<double> parse_double(std::string_view field) {
  if (field.size() > 1 && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

std::optional<std::size_t> parse_count(std::string_view field) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  const auto lower = [](char c) { return std::tolower(static_cast<unsigned char>(c)); };
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [&](char x, char y) { return lower(x) == lower(y); });
}

// At most the first 80 characters of `text`, for a message that quotes a file (a line of a
// 256 MiB file can be the whole file).
std::string excerpt(std::string_view text) {
  constexpr std::size_t kQuoted = 80;
  return text.size() <= kQuoted ? std::string(text) : std::string(text.substr(0, kQuoted)) + "...";
}

// Reads lines one by one, knows their numbers, and words errors as "source:line: reason: 'line'".
class LineSource {
 public:
  LineSource(std::istream& in, std::string_view source_name) : in_(in), source_name_(source_name) {}

  bool next() {
    if (!std::getline(in_, line_)) return false;
    ++number_;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    return true;
  }
  const std::string& line() const { return line_; }
  std::size_t number() const { return number_; }

  [[noreturn]] void fail(const std::string& reason) const {
    throw std::runtime_error(source_name_ + ":" + std::to_string(number_) + ": " + reason + ": '" + excerpt(line_) +
                             "'");
  }
  [[noreturn]] void fail_at_end(const std::string& reason) const {
    throw std::runtime_error(source_name_ + ": " + reason);
  }

 private:
  std::istream& in_;
  std::string source_name_;
  std::string line_;
  std::size_t number_ = 0;
};

// Where a particle line keeps its coordinates and radius.
struct ColumnLayout {
  std::size_t min_fields;
  std::size_t max_fields;
  std::size_t x_field;                      // y and z follow
  std::optional<std::size_t> radius_field;  // used if the line has that many fields
  std::string description;
};

const ColumnLayout plain_layout{3, 4, 0, 3, "3 or 4 numbers (x y z [radius])"};
const ColumnLayout xyz_layout{4, 5, 1, 4, "4 or 5 fields (species x y z [radius])"};

// The layout an extended-XYZ comment line declares with "Properties=name:type:columns:...", or
// nullopt if it declares none.
std::optional<ColumnLayout> declared_layout(const LineSource& source) {
  constexpr std::string_view key = "properties=";
  for (std::string_view field : split_fields(source.line())) {
    if (field.size() <= key.size() || !equals_ignoring_case(field.substr(0, key.size()), key)) continue;
    std::string_view spec = field.substr(key.size());
    if (spec.size() >= 2 && spec.front() == '"' && spec.back() == '"') spec = spec.substr(1, spec.size() - 2);

    std::vector<std::string_view> parts;
    for (std::size_t begin = 0;;) {
      const std::size_t end = spec.find(':', begin);
      parts.push_back(spec.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
      if (end == std::string_view::npos) break;
      begin = end + 1;
    }
    if (parts.size() % 3 != 0) source.fail("Properties must be name:type:columns triples");

    std::size_t column = 0;
    std::optional<std::size_t> position_column;
    std::optional<std::size_t> radius_column;
    for (std::size_t i = 0; i < parts.size(); i += 3) {
      const std::optional<std::size_t> width = parse_count(parts[i + 2]);
      if (!width || *width == 0) source.fail("Properties column count '" + std::string(parts[i + 2]) + "' is invalid");
      if (equals_ignoring_case(parts[i], "pos") && *width == 3) position_column = column;
      if (equals_ignoring_case(parts[i], "radius") && *width == 1) radius_column = column;
      column += *width;
    }
    if (!position_column) source.fail("Properties declares no pos:R:3 column");
    return ColumnLayout{column, column, *position_column, radius_column,
                        std::to_string(column) + " fields (per Properties)"};
  }
  return std::nullopt;
}

double finite_number(const LineSource& source, std::string_view field) {
  const std::optional<double> value = parse_double(field);
  if (!value) source.fail("'" + excerpt(field) + "' is not a number");
  if (!std::isfinite(*value)) source.fail("'" + excerpt(field) + "' is not finite");
  return *value;
}

void read_particle_line(const LineSource& source, const ColumnLayout& layout, double default_radius, Cluster& cluster) {
  const std::vector<std::string_view> fields = split_fields(source.line());
  if (fields.size() < layout.min_fields || fields.size() > layout.max_fields)
    source.fail("expected " + layout.description + ", found " + std::to_string(fields.size()) + " fields");
  const Vec3 position{finite_number(source, fields[layout.x_field]), finite_number(source, fields[layout.x_field + 1]),
                      finite_number(source, fields[layout.x_field + 2])};
  double radius = default_radius;
  if (layout.radius_field && *layout.radius_field < fields.size())
    radius = finite_number(source, fields[*layout.radius_field]);
  if (!(radius > 0.0)) source.fail("radius must be positive");
  cluster.position.push_back(position);
  cluster.radius.push_back(radius);
}

bool is_blank_or_comment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t\r\v\f");
  return first == std::string_view::npos || line[first] == '#';
}

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t\r\v\f") == std::string_view::npos; }

// XYZ form; `source` stands on the count line.
Cluster read_counted_form(LineSource& source, std::size_t count, double default_radius) {
  if (count == 0) source.fail("the particle count is zero");
  if (!source.next()) source.fail_at_end("the comment line after the particle count is missing");
  const ColumnLayout layout = declared_layout(source).value_or(xyz_layout);

  Cluster cluster;
  for (std::size_t i = 0; i < count; ++i) {
    if (!source.next())
      source.fail_at_end("line 1 announces " + std::to_string(count) + " particles but only " + std::to_string(i) +
                         " particle lines follow");
    read_particle_line(source, layout, default_radius, cluster);
  }
  while (source.next())
    if (!is_blank(source.line()))
      source.fail("more lines than the " + std::to_string(count) + " particles announced on line 1");
  return cluster;
}

// Plain form; `source` stands on the first line.
Cluster read_plain_form(LineSource& source, double default_radius) {
  Cluster cluster;
  do {
    if (!is_blank_or_comment(source.line())) read_particle_line(source, plain_layout, default_radius, cluster);
  } while (source.next());
  return cluster;
}

// ---- writing ----------------------------------------------------------------------------------

// Appends the shortest decimal form of `value` that reads back as the same double.
void append_number(std::string& line, double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  line.append(buffer, error == std::errc() ? end : buffer);
}

void append_particle(std::string& line, const Vec3& position, double radius) {
  append_number(line, position.x);
  line += ' ';
  append_number(line, position.y);
  line += ' ';
  append_number(line, position.z);
  line += ' ';
  append_number(line, radius);
  line += '\n';
}

void require_written(const std::ostream& out, const std::string& what) {
  if (!out) throw std::runtime_error("could not write " + what);
}

std::ofstream open_for_writing(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot open for writing: " + path.string());
  return out;
}

}  // namespace

Cluster read_xyz_cluster(std::istream& in, double default_radius, std::string_view source_name) {
  if (!(default_radius > 0.0) || !std::isfinite(default_radius))
    throw std::invalid_argument("default radius must be positive and finite");
  LineSource source(in, source_name);
  if (!source.next()) source.fail_at_end("no particles");

  const std::vector<std::string_view> first = split_fields(source.line());
  const std::optional<std::size_t> count = first.size() == 1 ? parse_count(first[0]) : std::nullopt;
  Cluster cluster = count ? read_counted_form(source, *count, default_radius) : read_plain_form(source, default_radius);
  if (cluster.size() == 0) source.fail_at_end("no particles");
  return cluster;
}

Cluster read_xyz_cluster(const std::filesystem::path& path, double default_radius) {
  std::istringstream in(read_regular_file(path, kMaxClusterTextBytes, "cluster file"));
  return read_xyz_cluster(in, default_radius, path.string());
}

void write_xyz_cluster(std::ostream& out, const Cluster& cluster) {
  if (cluster.radius.size() != cluster.position.size())
    throw std::invalid_argument("cluster has " + std::to_string(cluster.position.size()) + " positions but " +
                                std::to_string(cluster.radius.size()) + " radii");
  std::string text = "# aerobreak cluster, " + std::to_string(cluster.size()) + " primaries; columns: x y z radius\n";
  for (std::size_t i = 0; i < cluster.size(); ++i) append_particle(text, cluster.position[i], cluster.radius[i]);
  out << text;
  require_written(out, "XYZ cluster");
}

void write_xyz_cluster(const std::filesystem::path& path, const Cluster& cluster) {
  std::ofstream out = open_for_writing(path);
  write_xyz_cluster(out, cluster);
  out.close();
  require_written(out, "XYZ cluster to " + path.string());
}

void write_xyz_frame(std::ostream& out, const Particles& particles, std::string_view comment) {
  if (comment.find_first_of("\r\n") != std::string_view::npos)
    throw std::invalid_argument("an XYZ comment must be a single line");
  if (particles.radius.size() != particles.size())
    throw std::invalid_argument("particles have " + std::to_string(particles.size()) + " positions but " +
                                std::to_string(particles.radius.size()) + " radii");
  // Extended XYZ: the comment line declares the columns, so OVITO and ASE need no column mapping.
  std::string text = std::to_string(particles.size()) + "\nProperties=species:S:1:pos:R:3:radius:R:1";
  if (!comment.empty()) text.append(" ").append(comment);
  text += '\n';
  for (std::size_t i = 0; i < particles.size(); ++i) {
    text += "P ";
    append_particle(text, particles.position[i], particles.radius[i]);
  }
  out << text;
  require_written(out, "XYZ frame");
}

}  // namespace aerobreak
