# Install rules and the CMake package: `cmake --install build --prefix DIR` puts the program, the
# static libraries clumpkit::geom, clumpkit::dem and clumpkit::io, the public headers (and the
# headers they include) under include/clumpkit, the recipes, the docs and
# lib/cmake/clumpkit/clumpkitConfig.cmake, so a C++ project writes find_package(clumpkit).
#
# Static libraries: a consumer links one self-contained binary (no SONAME or ABI to keep stable
# between releases while the API still moves, no LD_LIBRARY_PATH for a prefix outside the
# system's), and the Python module already links them the same way; their dependencies travel
# with the exported targets (find_dependency in the config file).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CLUMPKIT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/clumpkit)
set(CLUMPKIT_HEADER_DIR ${CMAKE_INSTALL_INCLUDEDIR}/clumpkit)

# The public headers: those a user calls (the fill, union volumes, descriptors, shapes, mesh and
# clump files, the World and the specimen API) and those they include. Only these are installed;
# the rest stay private (docs/layout.md, "Public headers"). Configuring fails when a public
# header includes a private one, so the set stays closed.
set(CLUMPKIT_PUBLIC_HEADERS
    geom/vec.h geom/mesh/mesh.h geom/sphere.h geom/errors.h geom/progress.h geom/format.h
    geom/random.h geom/range.h geom/version.h
    geom/mesh/mesh_index.h
    geom/fill/fill.h geom/fill/fill_options.h geom/fill/distance_field.h geom/fill/fidelity.h
    geom/volume/union_of_balls.h geom/volume/inclusion_exclusion.h geom/volume/slicing.h
    geom/volume/voxel_volume.h
    geom/descriptors/descriptors.h
    geom/shapes/block.h geom/shapes/hull.h geom/shapes/polyhedron.h geom/shapes/primitives.h
    geom/template/clump_template.h
    io/formats/mesh_io.h io/formats/clump_io.h io/formats/specimen_csv.h
    dem/core/world.h dem/core/body.h dem/core/bond.h dem/core/bond_moments.h
    dem/core/cohesive_law.h dem/core/contact.h dem/core/neighbour_search.h dem/core/wall.h
    dem/measure/region_volume.h dem/run/stage_store.h
    dem/specimen/specimen.h dem/specimen/placement.h dem/specimen/specimen_particles.h)
# The list, for the install test (tests/install/install_test.sh).
string(REPLACE ";" "\n" public_list "${CLUMPKIT_PUBLIC_HEADERS}")
file(WRITE ${CMAKE_BINARY_DIR}/public_headers.txt "${public_list}\n")
foreach(h IN LISTS CLUMPKIT_PUBLIC_HEADERS)
  file(STRINGS ${PROJECT_SOURCE_DIR}/${h} lines REGEX "^#include \"")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" inc "${line}")
    if(EXISTS ${PROJECT_SOURCE_DIR}/${inc} AND NOT inc IN_LIST CLUMPKIT_PUBLIC_HEADERS)
      message(FATAL_ERROR "install: the public header ${h} includes ${inc}, which is not public "
                          "(cmake/install.cmake: make it public or drop the include)")
    endif()
  endforeach()
  get_filename_component(dir ${h} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${h} DESTINATION ${CLUMPKIT_HEADER_DIR}/${dir})
endforeach()

set_target_properties(clumpkit_geom PROPERTIES EXPORT_NAME geom)
set_target_properties(clumpkit_dem PROPERTIES EXPORT_NAME dem)
set_target_properties(clumpkit_io PROPERTIES EXPORT_NAME io)
# The two Debian libraries without a CMake package travel as imported interface targets.
set_target_properties(clumpkit_opencv PROPERTIES EXPORT_NAME opencv)
set_target_properties(clumpkit_voro PROPERTIES EXPORT_NAME voro)
install(TARGETS clumpkit_geom clumpkit_dem clumpkit_io clumpkit_opencv clumpkit_voro
        EXPORT clumpkitTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}/clumpkit)
install(TARGETS clumpkit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT clumpkitTargets NAMESPACE clumpkit:: DESTINATION ${CLUMPKIT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/clumpkitConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/clumpkitConfig.cmake
                              INSTALL_DESTINATION ${CLUMPKIT_CMAKE_DIR})
# 0.x: a minor release may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/clumpkitConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/clumpkitConfig.cmake ${CMAKE_BINARY_DIR}/clumpkitConfigVersion.cmake
        DESTINATION ${CLUMPKIT_CMAKE_DIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/recipes DESTINATION ${CMAKE_INSTALL_DATADIR}/clumpkit)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/COPYING DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)

# The Python module beside the program, where Debian's python3 finds it (the prefix's
# lib/python3/dist-packages: /usr/lib/python3/dist-packages in the package).
if(CLUMPKIT_PYTHON)
  set(CLUMPKIT_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
      "Where `cmake --install` puts the Python package clumpkit, relative to the prefix")
  install(DIRECTORY ${CMAKE_BINARY_DIR}/python/clumpkit DESTINATION ${CLUMPKIT_PYTHON_INSTALL_DIR}
          PATTERN __pycache__ EXCLUDE)
endif()

# Man pages from the program's --help (help2man, by cmake/man_pages.sh): clumpkit(1) and one per
# command as `clumpkit --help` lists them, clumpkit-fill(1) and so on. Built with everything when
# help2man is there (scripts/deps installs it).
find_program(HELP2MAN help2man)
if(HELP2MAN)
  add_custom_command(
    OUTPUT ${CMAKE_BINARY_DIR}/man/clumpkit.1
    COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/man_pages.sh $<TARGET_FILE:clumpkit>
            ${CMAKE_BINARY_DIR}/man ${PROJECT_VERSION}
    DEPENDS clumpkit ${PROJECT_SOURCE_DIR}/cmake/man_pages.sh VERBATIM)
  add_custom_target(clumpkit_man ALL DEPENDS ${CMAKE_BINARY_DIR}/man/clumpkit.1)
  install(DIRECTORY ${CMAKE_BINARY_DIR}/man/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
          FILES_MATCHING PATTERN "*.1")
endif()

include(${PROJECT_SOURCE_DIR}/cmake/package.cmake)
