# `cpack -G DEB` in the build folder: ncvm_VERSION_ARCH.deb for Debian 12 (installs to /usr).
# The shared libraries it needs (fmt, Clipper, zlib, OpenSSL, brotli) become Depends through
# dpkg-shlibdeps; the Python module wants Debian's python3 and numpy.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ncvm)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the ncvm authors")
set(CPACK_PACKAGE_CONTACT "the ncvm authors <ncvm@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Fanuc-compatible CNC control emulator")
set(CPACK_PACKAGE_DESCRIPTION
    "Runs Fanuc part programs (G code, Custom Macro B) for lathes and machining centres as the control would, and reports moves, cycle time, end state and alarms; with a web viewer, a C++ library and a Python module.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-matplotlib, chromium | firefox-esr")
# The tests, benchmarks and fuzz targets install nothing; the package holds what
# NcvmInstall.cmake lists.
include(CPack)
