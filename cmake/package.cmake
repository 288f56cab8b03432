# The Debian package (`cpack -G DEB` in build/, run by scripts/package): everything
# `cmake --install` puts under /usr — the program, its man pages, the Python module in
# /usr/lib/python3/dist-packages, the libraries, headers and CMake package for C++ users, the
# recipes and docs. Depends is computed by dpkg-shlibdeps from the program and the module, plus
# what they use at run time without linking it.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME clumpkit)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "clumpkit developers")
set(CPACK_PACKAGE_CONTACT "clumpkit developers <clumpkit@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "irregular particles, sphere clumps and DEM specimens for geomaterials")
# One string (set() with several would join them with ';').
string(CONCAT CPACK_PACKAGE_DESCRIPTION
       "Rock blocks, convex hulls and cut polyhedra as meshes; maximal-inscribed-sphere fills with "
       "exact union volumes and mass properties; dense DEM specimens; exports to LAMMPS, "
       "LIGGGHTS, Yade, PFC and ParaView; element tests, the cone penetration test and particle "
       "crushing. The package also holds the C++ libraries, headers and CMake package; building "
       "against them needs the -dev packages of their dependencies (docs/install.md).")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/COPYING)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Used without being linked: three.js is copied beside every page, NumPy is what the module's
# arrays are, and python3 runs the module.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libjs-three, python3, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "lammps, openmpi-bin, yade, liggghts, paraview")
include(CPack)
