// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_INPUT_HELPERS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_INPUT_HELPERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <iterator>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

// Counts the offenders of one problem class and remembers the one of smallest
// index, so that messages name the first offender in index (= file) order
// whatever the iteration order of the mesh.
struct Input_offenders
{
  std::size_t count = 0;
  std::size_t first = Input_error::no_element;
  std::string first_detail;

  template <typename Describe>
  void add(std::size_t index, const Describe& describe)
  {
    ++count;
    if(first == Input_error::no_element || index < first) {
      first = index;
      first_detail = describe();
    }
  }

  bool empty() const { return count == 0; }

  [[noreturn]] void raise(Input_problem problem, const std::string& what_plural,
                          const std::string& where = std::string()) const
  {
    std::ostringstream os;
    os << first_detail << where << " (" << count << " " << what_plural << " in total)";
    throw Input_error(problem, os.str(), first);
  }
};

inline std::string input_lowercase_extension(const std::string& path)
{
  const std::string::size_type dot = path.rfind('.');
  const std::string::size_type slash = path.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Whether the three coordinates of a point are finite (not NaN, not infinite).
template <typename Point>
bool input_is_finite(const Point& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

// A token that strtod reads entirely as NaN or infinity ("nan", "inf", "1e999").
inline bool input_is_non_finite_token(const std::string& token)
{
  if(token.empty())
    return false;
  char* end = nullptr;
  const double d = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !std::isfinite(d);
}

// CGAL's ASCII readers stop at "nan" or "inf" and only return false; this scan
// runs after such a failure, to name the vertex instead of blaming the file.
// Returns the 0-based vertex index, or no_element. Handles ASCII OFF and OBJ.
inline std::size_t input_find_non_finite_vertex_in_ascii_file(const std::string& path,
                                                             const std::string& ext)
{
  std::ifstream in(path);
  if(!in)
    return Input_error::no_element;
  std::string line;
  auto strip_comment = [](std::string& l) {
    const std::string::size_type hash = l.find('#');
    if(hash != std::string::npos) l.erase(hash);
  };

  if(ext == "obj") {
    std::size_t vertex = 0;
    while(std::getline(in, line)) {
      strip_comment(line);
      std::istringstream ls(line);
      std::string key;
      if(!(ls >> key) || key != "v")
        continue;
      std::string c;
      for(int i = 0; i < 3 && (ls >> c); ++i)
        if(input_is_non_finite_token(c))
          return vertex;
      ++vertex;
    }
    return Input_error::no_element;
  }

  if(ext != "off")
    return Input_error::no_element;

  // OFF: header keyword, then "nv nf ne" (possibly on the header line), then nv vertex lines.
  std::vector<std::string> counts;
  bool header_seen = false;
  std::size_t nv = 0;
  while(std::getline(in, line)) {
    strip_comment(line);
    std::istringstream ls(line);
    std::string tok;
    while(ls >> tok) {
      if(!header_seen) {
        header_seen = true;
        if(tok.size() >= 3 && tok.compare(tok.size() - 3, 3, "OFF") == 0)
          continue;                       // "OFF", "COFF", "NOFF", ...
      }
      if(tok == "BINARY")
        return Input_error::no_element;
      counts.push_back(tok);
    }
    if(counts.size() >= 3)
      break;
  }
  if(counts.size() < 3)
    return Input_error::no_element;
  nv = std::size_t(std::strtoull(counts[0].c_str(), nullptr, 10));
  std::size_t vertex = 0;
  while(vertex < nv && std::getline(in, line)) {
    strip_comment(line);
    std::istringstream ls(line);
    std::string c;
    int read = 0;
    for(; read < 3 && (ls >> c); ++read)
      if(input_is_non_finite_token(c))
        return vertex;
    if(read > 0)
      ++vertex;
  }
  return Input_error::no_element;
}

// Records which points PMP::orient_polygon_soup() duplicated: CGAL does not
// return that mapping.
struct Input_orientation_visitor : public CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<std::pair<std::size_t, std::size_t> >* duplicates; // (original, copy)

  explicit Input_orientation_visitor(std::vector<std::pair<std::size_t, std::size_t> >& d) : duplicates(&d) {}

  void duplicated_vertex(std::size_t original, std::size_t copy)
  { duplicates->emplace_back(original, copy); }
};

// Surface_mesh keeps removed elements as garbage, which breaks the "indices
// are 0..n-1" assumption of index-based code; other meshes have no garbage.
template <typename TriangleMesh>
void input_collect_garbage(TriangleMesh&) {}

template <typename P>
void input_collect_garbage(CGAL::Surface_mesh<P>& sm)
{
  if(sm.has_garbage())
    sm.collect_garbage();
}

// Glues each copy made by PMP::orient_polygon_soup() for a singular (pinched)
// vertex back onto its original, so that the mesh read from a file has the
// file's vertices and PMP::non_manifold_vertices() can report them. CGAL's
// halfedge structures represent such vertices (an umbrella per fan); it is the
// inverse of PMP::duplicate_non_manifold_vertices().
template <typename TriangleMesh>
void input_merge_duplicated_vertices(
    TriangleMesh& tm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_of_point,
    const std::vector<std::pair<std::size_t, std::size_t> >& duplicates)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  if(duplicates.empty())
    return;
  for(const auto& od : duplicates) {
    const vertex_descriptor o = vertex_of_point[od.first];
    const vertex_descriptor d = vertex_of_point[od.second];
    const halfedge_descriptor hd = halfedge(d, tm);
    if(hd == boost::graph_traits<TriangleMesh>::null_halfedge())
      continue;
    std::vector<halfedge_descriptor> fan;
    halfedge_descriptor border = boost::graph_traits<TriangleMesh>::null_halfedge();
    for(halfedge_descriptor h : halfedges_around_target(hd, tm)) {
      fan.push_back(h);
      if(is_border(h, tm)) border = h;
    }
    for(halfedge_descriptor h : fan)
      set_target(h, o, tm);
    // keep a border halfedge as halfedge(o) when there is one, as CGAL does for border vertices
    if(border != boost::graph_traits<TriangleMesh>::null_halfedge() && !is_border(halfedge(o, tm), tm))
      set_halfedge(o, border, tm);
    remove_vertex(d, tm);
  }
  input_collect_garbage(tm);
}

// The number of elements of a range. num_vertices() & co. are no counts for
// a Surface_mesh with removed elements: they include the removed ones.
template <typename Range>
std::size_t input_count(const Range& r)
{
  return std::size_t(std::distance(r.begin(), r.end()));
}

// Index maps must be a bijection onto 0..n-1: every stage stores per-element
// data in vectors indexed by them.
template <typename Range, typename IndexMap>
void input_check_index_map(const Range& elements, const IndexMap& index, const char* what)
{
  const std::size_t n = input_count(elements);
  std::vector<bool> seen(n, false);
  for(const auto& e : elements) {
    const std::size_t i = std::size_t(get(index, e));
    if(i >= n || seen[i]) {
      std::ostringstream os;
      os << "the " << what << " index map gives " << (i >= n ? "index " : "twice the index ") << i
         << ", it must number the " << n << " " << what
         << "s from 0 (a CGAL::Surface_mesh with removed elements needs collect_garbage())";
      throw Input_error(Input_problem::invalid_parameter, os.str());
    }
    seen[i] = true;
  }
}

// number_of_samples may come as the package's tag or as CGAL's own tag.
template <typename NP>
bool input_number_of_samples(const NP& np, long long& n)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  if(!is_default_parameter<NP, internal_np::number_of_samples_t>::value) {
    n = (long long)choose_parameter(get_parameter(np, internal_np::number_of_samples), 0);
    return true;
  }
  if(!is_default_parameter<NP, CGAL::internal_np::number_of_samples_t>::value) {
    n = (long long)choose_parameter(get_parameter(np, CGAL::internal_np::number_of_samples), 0);
    return true;
  }
  return false;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_INPUT_HELPERS_H
