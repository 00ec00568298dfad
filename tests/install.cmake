# CTest entry for the install: `cmake --install` into a temporary prefix, the prefix moved, then the
# moved bin/dspbr run from another folder and examples/ built against the moved CMake package
# (tests/install_test.sh; ~1-2 minutes, mostly the example's compile and validate --quick).
if(DSPBR_INSTALL)
  add_test(NAME install_relocated
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/install_test.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR}
                   ${PROJECT_BINARY_DIR}/install-test ${CMAKE_COMMAND})
  set_tests_properties(install_relocated PROPERTIES TIMEOUT 300)
endif()
