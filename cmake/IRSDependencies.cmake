# Finds the package's dependencies; shared by the build tree and the installed
# package config, so that a downstream project gets exactly the same set-up.
find_package(CGAL REQUIRED)
find_package(Eigen3 3.3.0 REQUIRED NO_MODULE)
include(CGAL_Eigen3_support)
# Spectra (header-only, on Eigen): the Laplace-Beltrami eigenfunctions of the
# spectral refinement of the symmetric map
find_package(spectra 1.0 REQUIRED CONFIG)
find_package(TBB QUIET)
include(CGAL_TBB_support)

function(irs_link_dependencies target)
  target_link_libraries(${target} INTERFACE CGAL::CGAL CGAL::Eigen3_support Spectra::Spectra)
  if(TARGET CGAL::TBB_support)
    target_link_libraries(${target} INTERFACE CGAL::TBB_support)
  endif()
endfunction()
