// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_MERGE_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_MERGE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/segmentation_graph.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>
#include <vector>

// The two segmentations of the paper's Sec. 4.1 on flat arrays (by face index).

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

// From a face labelling (region id >= 0, or -1 for uncovered) to connected
// segments: every connected component of equal labels is a candidate
// segment; those with less than `minimum_area`, and those flagged in
// `force` (by label, when the label is in it), join the neighbour they share
// the longest boundary with. Returns the number of segments.
inline std::size_t finish_segments(const Face_graph& g, const std::vector<long>& label, double minimum_area,
                                   bool merge_uncovered, std::vector<std::size_t>& segment)
{
  const std::size_t n = label_components(g, label, segment);
  std::vector<char> force(n, 0);
  if(merge_uncovered)
    for(std::size_t f = 0; f < g.number_of_faces; ++f)
      if(label[f] < 0) force[segment[f]] = 1;
  return merge_small_components(g, segment, n, minimum_area, (std::numeric_limits<std::size_t>::max)(), &force);
}

// Paper Sec. 4.1, merging: every connected part of the over-segmentation
// goes to the region covering the largest area of it (ties: the smaller
// region id), if that region covers at least `minimum_coverage` of the part;
// a part no region covers so much of (it straddles regions, or none touches
// it) stays a segment of its own (`merge_uncovered == false`) or joins its
// neighbours. Then finish_segments().
//
// With `axis_faces` (by face: 1 where the face touches its region's curve),
// only the parts the curve crosses (at least `minimum_axis_faces` such faces)
// merge into their region's segment, the symmetric core; the other parts of
// the region, the mirror halves of pairs of parts, stay segments of their own.
inline std::size_t merge_parts(const Face_graph& g, const std::vector<long>& region, const std::vector<long>& part,
                               double minimum_area, bool merge_uncovered, double minimum_coverage,
                               std::vector<std::size_t>& segment, const std::vector<char>* axis_faces = nullptr,
                               std::size_t minimum_axis_faces = 3)
{
  std::vector<std::size_t> comp;
  const std::size_t nc = label_components(g, part, comp); // parts must be connected: split them
  long number_of_regions = 0;
  for(long r : region) number_of_regions = (std::max)(number_of_regions, r + 1);
  std::vector<std::map<long, double>> cover(nc);
  std::vector<double> part_area(nc, 0.);
  for(std::size_t f = 0; f < g.number_of_faces; ++f)
  {
    part_area[comp[f]] += g.area[f];
    if(region[f] >= 0) cover[comp[f]][region[f]] += g.area[f];
  }
  std::vector<long> assigned(nc, -1);
  for(std::size_t c = 0; c < nc; ++c)
  {
    double best = 0.;
    for(const auto& ra : cover[c]) // increasing region id: ties go to the smaller one
      if(ra.second > best && ra.second >= minimum_coverage * part_area[c]) { best = ra.second; assigned[c] = ra.first; }
  }
  if(axis_faces != nullptr)
  {
    std::vector<std::size_t> crossed(nc, 0);
    for(std::size_t f = 0; f < g.number_of_faces; ++f)
      crossed[comp[f]] += ((*axis_faces)[f] != 0 && region[f] >= 0 && region[f] == assigned[comp[f]]);
    for(std::size_t c = 0; c < nc; ++c)
      if(assigned[c] >= 0 && crossed[c] < minimum_axis_faces) assigned[c] = -2; // off the axis: own segment
  }
  std::vector<long> label(g.number_of_faces);
  for(std::size_t f = 0; f < g.number_of_faces; ++f)
  {
    const long a = assigned[comp[f]];
    // uncovered parts keep their own label (distinct from every region) unless they are to be merged
    label[f] = a >= 0 ? a : ((a == -1 && merge_uncovered) ? -1 : number_of_regions + long(comp[f]));
  }
  return finish_segments(g, label, minimum_area, merge_uncovered, segment);
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SEGMENTATION_MERGE_H
