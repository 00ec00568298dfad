# The conformance kit's diagnosis on deliberately wrong implementations (docs/conformance.md,
# "Diagnosis"): each classic mistake of tests/shader_library/seeded_mistakes.json is a patched copy
# of the shader library (seed_mistakes.py, its own namespace), compiled as C++ (float);
# seeded_mistakes writes each one's results over the default vector set (fixture seeded_results),
# and seeded_mistake_NAME asserts that `dspbr conformance check` fails it and ranks the mistake's
# cause first in report.json, explaining 90 % of the failures or more and contradicted by no passing
# vector (seeded_check.sh). The diagnosis is the reference made with each
# cause of its vocabulary (src/dspbr/conformance/diagnosis.cpp): code apart from the patches.
set(_sm ${CMAKE_CURRENT_LIST_DIR}/shader_library)
set(_sm_dir ${PROJECT_BINARY_DIR}/seeded-mistakes)
file(READ ${_sm}/seeded_mistakes.json _sm_json)
string(JSON _sm_count LENGTH "${_sm_json}" mistakes)
math(EXPR _sm_last "${_sm_count} - 1")
set(_sm_names)
set(_sm_list "")
foreach(i RANGE ${_sm_last})
  string(JSON _name GET "${_sm_json}" mistakes ${i} name)
  list(APPEND _sm_names ${_name})
  string(APPEND _sm_list "SEEDED(${_name})\n")
endforeach()
file(CONFIGURE OUTPUT ${_sm_dir}/seeded_list.h CONTENT "${_sm_list}")
file(GLOB _sm_library ${PROJECT_SOURCE_DIR}/shaders/dspbr.h ${PROJECT_SOURCE_DIR}/shaders/dspbr/*)
add_custom_command(OUTPUT ${_sm_dir}/copies.stamp
  COMMAND /usr/bin/python3 ${_sm}/seed_mistakes.py ${PROJECT_SOURCE_DIR}/shaders ${_sm}/seeded_mistakes.json ${_sm_dir}
  COMMAND ${CMAKE_COMMAND} -E touch ${_sm_dir}/copies.stamp
  DEPENDS ${_sm}/seed_mistakes.py ${_sm}/seeded_mistakes.json ${_sm_library}
  COMMENT "seed_mistakes.py: the shader library's seeded copies" VERBATIM)
add_custom_target(seeded_copies DEPENDS ${_sm_dir}/copies.stamp)
set(_sm_objects)
foreach(_name ${_sm_names})
  add_library(seeded_${_name} OBJECT ${_sm}/seeded_eval.cpp)
  target_include_directories(seeded_${_name} PRIVATE ${_sm_dir}/${_name} ${_sm_dir} ${_sm} ${PROJECT_SOURCE_DIR}/luts
                             ${PROJECT_SOURCE_DIR}/fits)
  target_compile_definitions(seeded_${_name} PRIVATE SEEDED_NS=dspbr_seeded_${_name} SEEDED_FN=seeded_eval_${_name})
  target_compile_features(seeded_${_name} PRIVATE cxx_std_17)
  add_dependencies(seeded_${_name} seeded_copies)
  list(APPEND _sm_objects $<TARGET_OBJECTS:seeded_${_name}>)
endforeach()
add_executable(seeded_mistakes ${_sm}/seeded_mistakes.cpp ${_sm_objects})
target_include_directories(seeded_mistakes PRIVATE ${_sm} ${_sm_dir})
target_link_libraries(seeded_mistakes PRIVATE dspbr_shader_host dspbr_conformance)
target_compile_options(seeded_mistakes PRIVATE -Wall -Wextra)
add_test(NAME seeded_results
         COMMAND sh -c "rm -rf '${_sm_dir}/results' && mkdir -p '${_sm_dir}/results' && \
'$<TARGET_FILE:seeded_mistakes>' '${PROJECT_BINARY_DIR}/shader-vectors/vectors.json' '${_sm_dir}/results'")
set_tests_properties(seeded_results PROPERTIES FIXTURES_REQUIRED shader_vectors FIXTURES_SETUP seeded_results)
foreach(i RANGE ${_sm_last})
  string(JSON _name GET "${_sm_json}" mistakes ${i} name)
  string(JSON _cause GET "${_sm_json}" mistakes ${i} cause)
  add_test(NAME seeded_mistake_${_name}
           COMMAND bash ${_sm}/seeded_check.sh $<TARGET_FILE:dspbr> ${PROJECT_BINARY_DIR}/shader-vectors/vectors.json
                   ${_sm_dir}/results ${_name} ${_cause})
  set_tests_properties(seeded_mistake_${_name} PROPERTIES FIXTURES_REQUIRED seeded_results)
endforeach()
