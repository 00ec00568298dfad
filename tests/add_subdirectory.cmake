# CTest entry add_subdirectory_parent: configures tests/add_subdirectory/, a parent project that
# includes this project with add_subdirectory(), and builds its object library parent_check
# (headers through dspbr::dspbr, the generated version source): seconds, not the whole library.
add_test(NAME add_subdirectory_parent
         COMMAND bash -c "rm -rf '${PROJECT_BINARY_DIR}/add-subdirectory-test' && \"${CMAKE_COMMAND}\" -S '${CMAKE_CURRENT_LIST_DIR}/add_subdirectory' -B '${PROJECT_BINARY_DIR}/add-subdirectory-test' -DCMAKE_BUILD_TYPE=Release -DDSPBR_SOURCE='${PROJECT_SOURCE_DIR}' && \"${CMAKE_COMMAND}\" --build '${PROJECT_BINARY_DIR}/add-subdirectory-test' --target parent_check")
set_tests_properties(add_subdirectory_parent PROPERTIES TIMEOUT 300)
