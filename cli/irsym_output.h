// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Output helpers of the irsym tool: a tiny JSON writer, stage timing with peak
// memory, coloured PLY files and headless f3d pictures.

#ifndef IRSYM_OUTPUT_H
#define IRSYM_OUTPUT_H

#include <CGAL/IO/Color.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace irsym {

// Boost 1.74 has no Boost.JSON and property_tree writes every number as a
// string, so the report is written by this small emitter.
class Json
{
public:
  static Json object() { Json j; j.text_ = "{"; j.close_ = "}"; return j; }
  static Json array() { Json j; j.text_ = "["; j.close_ = "]"; return j; }

  Json& add(const std::string& key, const Json& value) { return raw(key, value.nested()); }
  Json& add(const std::string& key, const std::string& value) { return raw(key, quote(value)); }
  Json& add(const std::string& key, const char* value) { return raw(key, quote(value)); }
  Json& add(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  template <typename T,
            typename = std::enable_if_t<std::is_arithmetic<T>::value && !std::is_same<T, bool>::value>>
  Json& add(const std::string& key, T value) { return raw(key, number(double(value))); }
  Json& push(const Json& value) { return raw("", value.nested()); }
  Json& push(const std::string& value) { return raw("", quote(value)); }
  template <typename T, typename = std::enable_if_t<std::is_arithmetic<T>::value>>
  Json& push(T value) { return raw("", number(double(value))); }

  std::string str() const { return text_ + (first_ ? "" : "\n") + close_; }

private:
  // the text of a value nested one level deeper: every line indented once more
  std::string nested() const
  {
    std::string t;
    for(char c : str()) { t += c; if(c == '\n') t += "  "; }
    return t;
  }

public:

private:
  Json& raw(const std::string& key, const std::string& value)
  {
    if(!first_) text_ += ",";
    first_ = false;
    text_ += "\n  ";
    if(!key.empty()) text_ += quote(key) + ": ";
    text_ += value;
    return *this;
  }
  static std::string number(double v)
  {
    if(!std::isfinite(v)) return "null";
    std::ostringstream s;
    s << std::setprecision(10) << v;
    return s.str();
  }
  static std::string quote(const std::string& s)
  {
    std::string q = "\"";
    for(char c : s) {
      if(c == '"' || c == '\\') { q += '\\'; q += c; }
      else if(c == '\n') q += "\\n";
      else if(static_cast<unsigned char>(c) < 0x20) q += ' ';
      else q += c;
    }
    return q + "\"";
  }
  std::string text_, close_;
  bool first_ = true;
};

/// peak resident memory of the process so far, in MiB
inline double peak_memory_mib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0; // Linux reports KiB
}

/// wall time and peak memory of each stage, in the order they ran
class Stage_log
{
public:
  void start(const std::string& name)
  {
    name_ = name;
    timer_.reset();
    timer_.start();
    std::fprintf(stderr, "[irsym] %s ...\n", name.c_str());
  }
  void stop()
  {
    timer_.stop();
    stages_.push_back({name_, timer_.time(), peak_memory_mib()});
    std::fprintf(stderr, "[irsym] %s: %.3f s, peak %.0f MiB\n", name_.c_str(), timer_.time(),
                 stages_.back().peak_mib);
  }
  /// ends the current stage, cut short by a cancellation: recorded as "(stopped)"
  void abandon()
  {
    name_ += " (stopped)";
    stop();
  }
  Json to_json() const
  {
    Json a = Json::array();
    for(const Stage& s : stages_)
      a.push(Json::object().add("stage", s.name).add("seconds", s.seconds).add("peak_memory_mib", s.peak_mib));
    return a;
  }
  double total_seconds() const
  {
    double t = 0;
    for(const Stage& s : stages_) t += s.seconds;
    return t;
  }

private:
  struct Stage { std::string name; double seconds; double peak_mib; };
  std::vector<Stage> stages_;
  std::string name_;
  CGAL::Real_timer timer_;
};

/// a perceptually ordered blue-to-yellow map (viridis, 5 control points)
inline CGAL::IO::Color colour_map(double t)
{
  static const double c[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  if(!std::isfinite(t)) return CGAL::IO::Color(128, 128, 128);
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(int(t), 3);
  const double f = t - i;
  auto mix = [&](int k) { return static_cast<unsigned char>(std::lround(c[i][k] * (1 - f) + c[i + 1][k] * f)); };
  return CGAL::IO::Color(mix(0), mix(1), mix(2));
}

/// Writes `mesh` to `path` as binary PLY with a per-vertex scalar (named
/// `name`) and the matching colour; the colour scale spans the 1st to the
/// 99th percentile of the finite values, so that a few peaks do not flatten
/// the rest of the field. Written here rather than with CGAL::IO::write_PLY, which always adds
/// an alpha channel that f3d then renders as translucency.
template <typename Point>
bool write_scalar_ply(const CGAL::Surface_mesh<Point>& mesh, const std::vector<double>& values,
                      const std::string& name, const std::string& path)
{
  std::vector<double> finite;
  for(double v : values)
    if(std::isfinite(v)) finite.push_back(v);
  double lo = 0., hi = 1.;
  if(!finite.empty()) {
    std::sort(finite.begin(), finite.end());
    lo = finite[finite.size() / 100];
    hi = finite[finite.size() - 1 - finite.size() / 100];
  }
  const double range = hi > lo ? hi - lo : 1.0;

  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment irsym\n"
      << "element vertex " << mesh.number_of_vertices() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float " << name << "\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << mesh.number_of_faces() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  auto put = [&out](auto x) { out.write(reinterpret_cast<const char*>(&x), sizeof(x)); };
  for(auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    put(float(CGAL::to_double(p.x()))); put(float(CGAL::to_double(p.y()))); put(float(CGAL::to_double(p.z())));
    const double x = values.at(v.idx());
    put(float(x));
    const CGAL::IO::Color c = colour_map((x - lo) / range);
    put(c.red()); put(c.green()); put(c.blue());
  }
  for(auto f : mesh.faces()) {
    put(static_cast<unsigned char>(mesh.degree(f)));
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) put(static_cast<int>(v.idx()));
  }
  return bool(out);
}

/// a palette of well separated colours for labels (regions, segments); -1 is light grey
inline CGAL::IO::Color label_colour(long label)
{
  static const unsigned char c[12][3] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44},  {214, 39, 40},
                                         {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {188, 189, 34},
                                         {23, 190, 207}, {174, 199, 232}, {255, 187, 120}, {152, 223, 138}};
  if(label < 0) return CGAL::IO::Color(200, 200, 200);
  const auto& k = c[label % 12];
  return CGAL::IO::Color(k[0], k[1], k[2]);
}

/// Colours that show a vertex map: colour fields averaged over each vertex
/// and its partner, so that partners share a colour (where the map is an
/// involution; elsewhere nearly), a right mirror map gives a mirror-symmetric
/// picture and a part mapped wrong shows as a jump of colour; vertices
/// without a partner are dark grey. Of the `fields` (one value per vertex, in
/// one unit), the one of widest span after the averaging (over the mapped
/// vertices, 2nd to 98th percentile) gives the hue of a rainbow and the next
/// the brightness; a non-finite value takes the end of the scale.
inline std::vector<CGAL::IO::Color> partner_colours(const std::vector<std::ptrdiff_t>& partner,
                                                    const std::vector<std::vector<double>>& fields)
{
  const std::size_t n = partner.size(), k = fields.size();
  std::vector<std::vector<double>> mean(k, std::vector<double>(n, 0.)), values(k);
  std::vector<char> mapped(n, 0);
  for(std::size_t v = 0; v < n; ++v) {
    if(partner[v] < 0 || std::size_t(partner[v]) >= n) continue;
    mapped[v] = 1;
    for(std::size_t f = 0; f < k; ++f) { // the pair's mean: the same whichever of the two is v
      mean[f][v] = 0.5 * (fields[f].at(v) + fields[f].at(std::size_t(partner[v])));
      if(std::isfinite(mean[f][v])) values[f].push_back(mean[f][v]);
    }
  }
  // the span between the 2nd and 98th percentiles, so that a few pairs mapped
  // far apart do not flatten the colours of all the others
  std::vector<double> lo(k, 0.), hi(k, 1.);
  for(std::size_t f = 0; f < k; ++f) {
    std::vector<double>& x = values[f];
    if(x.empty()) continue;
    const std::size_t a = x.size() / 50, b = x.size() - 1 - x.size() / 50;
    std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(a), x.end());
    lo[f] = x[a];
    std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(b), x.end());
    hi[f] = x[b];
  }
  std::vector<std::size_t> by_span(k);
  std::iota(by_span.begin(), by_span.end(), std::size_t(0));
  std::sort(by_span.begin(), by_span.end(), [&](std::size_t a, std::size_t b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
  const auto unit = [&](std::size_t v, std::size_t f) {
    if(std::isnan(mean[f][v])) return 1.;
    return hi[f] > lo[f] ? (std::min)(1., (std::max)(0., (mean[f][v] - lo[f]) / (hi[f] - lo[f]))) : 0.5;
  };
  std::vector<CGAL::IO::Color> colours(n, CGAL::IO::Color(70, 70, 70));
  for(std::size_t v = 0; v < n; ++v) // hue from red (0) over yellow, green and cyan to blue (240 degrees)
    if(mapped[v])
      colours[v].set_hsv(k > 0 ? 240. * unit(v, by_span[0]) : 120., 80.,
                         60. + 40. * (k > 1 ? unit(v, by_span[1]) : 1.));
  return colours;
}

/// The three coordinates of each vertex of `mesh`, the fallback colour fields
/// of `partner_colours()` where no intrinsic ones are at hand
template <typename Point>
std::vector<std::vector<double>> coordinate_fields(const CGAL::Surface_mesh<Point>& mesh)
{
  std::vector<std::vector<double>> fields(3);
  for(const auto v : mesh.vertices())
    for(int axis = 0; axis < 3; ++axis) fields[std::size_t(axis)].push_back(CGAL::to_double(mesh.point(v)[axis]));
  return fields;
}

/// Writes `mesh` to `path` as binary PLY with a colour per vertex (same
/// reason as `write_scalar_ply()` for not using CGAL::IO::write_PLY).
template <typename Point>
bool write_coloured_ply(const CGAL::Surface_mesh<Point>& mesh, const std::vector<CGAL::IO::Color>& colours,
                        const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment irsym\n"
      << "element vertex " << mesh.number_of_vertices() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << mesh.number_of_faces() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  auto put = [&out](auto x) { out.write(reinterpret_cast<const char*>(&x), sizeof(x)); };
  for(auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    put(float(CGAL::to_double(p.x()))); put(float(CGAL::to_double(p.y()))); put(float(CGAL::to_double(p.z())));
    const CGAL::IO::Color& c = colours.at(v.idx());
    put(c.red()); put(c.green()); put(c.blue());
  }
  for(auto f : mesh.faces()) {
    put(static_cast<unsigned char>(mesh.degree(f)));
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) put(static_cast<int>(v.idx()));
  }
  return bool(out);
}

/// Writes `mesh` to `path` as binary PLY with a colour per face (segments).
template <typename Point>
bool write_face_coloured_ply(const CGAL::Surface_mesh<Point>& mesh, const std::vector<CGAL::IO::Color>& colours,
                             const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment irsym\n"
      << "element vertex " << mesh.number_of_vertices() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "element face " << mesh.number_of_faces() << "\n"
      << "property list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  auto put = [&out](auto x) { out.write(reinterpret_cast<const char*>(&x), sizeof(x)); };
  for(auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    put(float(CGAL::to_double(p.x()))); put(float(CGAL::to_double(p.y()))); put(float(CGAL::to_double(p.z())));
  }
  for(auto f : mesh.faces()) {
    put(static_cast<unsigned char>(mesh.degree(f)));
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) put(static_cast<int>(v.idx()));
    const CGAL::IO::Color& c = colours.at(f.idx());
    put(c.red()); put(c.green()); put(c.blue());
  }
  return bool(out);
}

inline bool command_exists(const std::string& name)
{
  return std::system(("command -v " + name + " > /dev/null 2>&1").c_str()) == 0;
}

/// Renders a coloured PLY to PNG with f3d under xvfb-run; false if unavailable.
/// `up` is the mesh axis drawn upwards (f3d's --up: +X, -Y, ...); the camera
/// looks from a three-quarter view so that curves on the mid-plane show.
inline bool render_png(const std::string& ply, const std::string& png, const std::string& up = "+Z",
                       bool face_colours = false)
{
  if(!command_exists("f3d") || !command_exists("xvfb-run")) return false;
  const std::string cmd = "xvfb-run -a -s '-screen 0 1280x1024x24' f3d --quiet --no-background=0 "
                          "--scalars=RGB --comp=-2 " + std::string(face_colours ? "--cells " : "") +
                          "--resolution=1200,900 --up=" + up +
                          " --camera-azimuth-angle=30 --camera-elevation-angle=15 "
                          "--output='" + png + "' '" + ply + "' > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

/// A picture of the outputs: `write(path)` writes DIR/NAME.ply (false on
/// failure, which throws, naming the file); then NAME.png is rendered where
/// f3d is installed. Both are listed in `files` (report.json) as they appear.
template <typename WritePly>
void write_picture(const std::filesystem::path& dir, const std::string& name, WritePly&& write, Json& files,
                   const std::string& up, bool face_colours = false)
{
  const std::string ply = (dir / (name + ".ply")).string();
  if(!write(ply)) throw std::runtime_error("cannot write " + ply);
  files.push(Json::object().add("file", name + ".ply"));
  if(render_png(ply, (dir / (name + ".png")).string(), up, face_colours))
    files.push(Json::object().add("file", name + ".png"));
}

} // namespace irsym

#endif // IRSYM_OUTPUT_H
