# dspbr::core alone (docs/install.md, "Components"): examples/core_renderer.cpp links dspbr_core
# only; its dynamic dependencies (ldd, transitive) must name none of Ceres, OpenImageIO, TBB or
# glog, and it must run (it checks a white rough metal's albedo). The installed package's
# components are checked from a moved prefix by install_relocated (tests/install_test.sh).
add_test(NAME core_links_alone
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/core_links_alone.sh $<TARGET_FILE:example_core_renderer>)
set_tests_properties(core_links_alone PROPERTIES TIMEOUT 60)
