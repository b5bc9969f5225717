# What `cmake --install` puts under the prefix (docs/embedding.md, "Installing"):
#   bin/ncvm, bin/ncvm-serve                    the command and the web viewer's server
#   share/ncvm/{macros,presets,examples,web}    found relative to bin/ (and to lib/) at run time
#   include/ncvm/, lib/libncvm.so               the C++ API
#   lib/cmake/ncvm/, lib/pkgconfig/ncvm.pc       find_package(ncvm) and pkg-config
#   lib/python3/dist-packages/ncvm/             the Python module (python/CMakeLists.txt)
#   share/man/man1/ncvm.1, share/bash-completion/completions/ncvm
#   share/doc/ncvm/{LICENSE,NOTICE,THIRD-PARTY-NOTICES}
# The rules for the binaries, share/ncvm and the web assets sit beside their targets
# (src/CMakeLists.txt, web/CMakeLists.txt).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/ncvm DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ncvm_shared EXPORT ncvmTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set(ncvm_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/ncvm)
install(EXPORT ncvmTargets NAMESPACE ncvm:: DESTINATION ${ncvm_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ncvmConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ncvmConfig.cmake
                              INSTALL_DESTINATION ${ncvm_cmake_dir})
# 0.x: a minor version may change the API; from 1.0 on, the major version.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ncvmConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ncvmConfig.cmake ${PROJECT_BINARY_DIR}/ncvmConfigVersion.cmake
        DESTINATION ${ncvm_cmake_dir})

# The .pc file finds the prefix from its own place, so an installed tree can move.
file(RELATIVE_PATH NCVM_PC_TO_PREFIX "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
configure_file(${PROJECT_SOURCE_DIR}/cmake/ncvm.pc.in ${PROJECT_BINARY_DIR}/ncvm.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/ncvm.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(FILES ${PROJECT_SOURCE_DIR}/docs/man/ncvm.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_SOURCE_DIR}/scripts/completion/ncvm.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME ncvm)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/NOTICE
              ${PROJECT_SOURCE_DIR}/THIRD-PARTY-NOTICES
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
