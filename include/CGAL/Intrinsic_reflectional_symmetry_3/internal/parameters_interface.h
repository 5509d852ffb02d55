// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// X-macro list of the package's named parameters. No include guard on purpose:
// parameters.h expands it several times.
//
// CGAL_IRS_add_named_parameter(tag type, tag value, setter name): names the
// package owns (they are not in CGAL 5.5's list).
// CGAL_IRS_import_named_parameter(tag type, setter name): CGAL's own names that
// the package reads, re-exposed so that own setters can follow them in a chain.

// preparation
CGAL_IRS_add_named_parameter(target_number_of_vertices_t, target_number_of_vertices, target_number_of_vertices)
CGAL_IRS_add_named_parameter(isotropic_remeshing_t, isotropic_remeshing, isotropic_remeshing)
CGAL_IRS_add_named_parameter(fill_holes_t, fill_holes, fill_holes)
CGAL_IRS_add_named_parameter(maximum_hole_boundary_length_t, maximum_hole_boundary_length, maximum_hole_boundary_length)
// sampling and geodesics
CGAL_IRS_add_named_parameter(number_of_samples_t, number_of_samples, number_of_samples)
CGAL_IRS_add_named_parameter(number_of_threads_t, number_of_threads, number_of_threads)
// signatures and the similarity filter
CGAL_IRS_add_named_parameter(number_of_signature_rings_t, number_of_signature_rings, number_of_signature_rings)
CGAL_IRS_add_named_parameter(signature_radius_t, signature_radius, signature_radius)
CGAL_IRS_add_named_parameter(sdf_cone_angle_t, sdf_cone_angle, sdf_cone_angle)
CGAL_IRS_add_named_parameter(sdf_number_of_rays_t, sdf_number_of_rays, sdf_number_of_rays)
CGAL_IRS_add_named_parameter(similarity_threshold_t, similarity_threshold, similarity_threshold)
// voting filters (paper section 3.3)
CGAL_IRS_add_named_parameter(distance_threshold_t, distance_threshold, distance_threshold)
CGAL_IRS_add_named_parameter(axial_threshold_t, axial_threshold, axial_threshold)
CGAL_IRS_add_named_parameter(distance_tolerance_floor_t, distance_tolerance_floor, distance_tolerance_floor)
CGAL_IRS_add_named_parameter(locality_radius_t, locality_radius, locality_radius)
CGAL_IRS_add_named_parameter(locality_min_points_t, locality_min_points, locality_min_points)
CGAL_IRS_add_named_parameter(maximum_number_of_voting_pairs_t, maximum_number_of_voting_pairs, maximum_number_of_voting_pairs)
CGAL_IRS_add_named_parameter(axial_sample_size_t, axial_sample_size, axial_sample_size)
CGAL_IRS_add_named_parameter(stopping_ratio_t, stopping_ratio, stopping_ratio)
CGAL_IRS_add_named_parameter(maximum_number_of_curves_t, maximum_number_of_curves, maximum_number_of_curves)
CGAL_IRS_add_named_parameter(pruning_threshold_t, pruning_threshold, pruning_threshold)
CGAL_IRS_add_named_parameter(vicinity_radius_t, vicinity_radius, vicinity_radius)
CGAL_IRS_add_named_parameter(symmetry_tolerance_t, symmetry_tolerance, symmetry_tolerance)
CGAL_IRS_add_named_parameter(close_curves_t, close_curves, close_curves)
CGAL_IRS_add_named_parameter(nested_symmetries_t, nested_symmetries, nested_symmetries)
CGAL_IRS_add_named_parameter(number_of_landmarks_t, number_of_landmarks, number_of_landmarks)
CGAL_IRS_add_named_parameter(number_of_local_rounds_t, number_of_local_rounds, number_of_local_rounds)
CGAL_IRS_add_named_parameter(number_of_eigenfunctions_t, number_of_eigenfunctions, number_of_eigenfunctions)
CGAL_IRS_add_named_parameter(vertex_region_map_t, vertex_region_map, vertex_region_map)
CGAL_IRS_add_named_parameter(initial_vertex_map_t, initial_vertex_map, initial_vertex_map)
CGAL_IRS_add_named_parameter(missing_part_threshold_t, missing_part_threshold, missing_part_threshold)
CGAL_IRS_add_named_parameter(maximum_number_of_rounds_t, maximum_number_of_rounds, maximum_number_of_rounds)
CGAL_IRS_add_named_parameter(over_segmenter_t, over_segmenter, over_segmenter)
CGAL_IRS_add_named_parameter(minimum_segment_area_t, minimum_segment_area, minimum_segment_area)
CGAL_IRS_add_named_parameter(merge_uncovered_parts_t, merge_uncovered_parts, merge_uncovered_parts)
CGAL_IRS_add_named_parameter(minimum_region_coverage_t, minimum_region_coverage, minimum_region_coverage)
CGAL_IRS_add_named_parameter(keep_off_axis_parts_t, keep_off_axis_parts, keep_off_axis_parts)

CGAL_IRS_import_named_parameter(vertex_point_t, vertex_point_map)
CGAL_IRS_import_named_parameter(geom_traits_t, geom_traits)
CGAL_IRS_import_named_parameter(vertex_index_t, vertex_index_map)
CGAL_IRS_import_named_parameter(face_index_t, face_index_map)
CGAL_IRS_import_named_parameter(random_seed_t, random_seed)
CGAL_IRS_import_named_parameter(number_of_iterations_t, number_of_iterations)
CGAL_IRS_import_named_parameter(callback_t, callback)
