# The generated lookup code compiles: the C header as strict C99 (an object library of the
# build), the GLSL and HLSL with glslangValidator (Debian glslang-tools) in both table modes
# (constant arrays; textures with DSPBR_LOOKUP_TEXTURES). Numbers: tests/test_lookup_code.cpp.
enable_language(C)
add_library(dspbr_lookup_c99 OBJECT ${CMAKE_CURRENT_LIST_DIR}/lookup_c99.c)
set_target_properties(dspbr_lookup_c99 PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(dspbr_lookup_c99 PRIVATE -Wall -Wextra -pedantic -Werror)
add_dependencies(dspbr_tests dspbr_lookup_c99)

find_program(DSPBR_GLSLANG glslangValidator)
if(DSPBR_GLSLANG)
  set(_luts ${PROJECT_SOURCE_DIR}/luts)
  set(_shaders ${CMAKE_CURRENT_LIST_DIR}/shaders)
  foreach(mode arrays textures)
    set(_def "")
    if(mode STREQUAL "textures")
      set(_def "-DDSPBR_LOOKUP_TEXTURES")
    endif()
    add_test(NAME lookup_glsl_${mode}
             COMMAND ${DSPBR_GLSLANG} -V ${_def} -I${_luts} -o ${CMAKE_CURRENT_BINARY_DIR}/lookup_glsl_${mode}.spv
                     ${_shaders}/lookup_test.frag)
    add_test(NAME lookup_hlsl_${mode}
             COMMAND ${DSPBR_GLSLANG} -D -V -S frag -e main ${_def} -I${_luts}
                     -o ${CMAKE_CURRENT_BINARY_DIR}/lookup_hlsl_${mode}.spv ${_shaders}/lookup_test.hlsl)
  endforeach()
else()
  message(WARNING "glslangValidator not found (Debian: glslang-tools): shader compile tests skipped")
endif()

# Hostile arguments (NaN, +-inf, +-1e30 in every argument of every public C lookup) under
# UndefinedBehaviorSanitizer and AddressSanitizer without recovery: no undefined conversion, no read
# outside a table, finite results in the documented range, NaN -> the low end (docs/luts.md).
add_executable(dspbr_lookup_nan ${CMAKE_CURRENT_LIST_DIR}/lookup_nan.c)
set_target_properties(dspbr_lookup_nan PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(dspbr_lookup_nan PRIVATE -O1 -g -Wall -Wextra -pedantic -Werror
                       -fsanitize=undefined,address -fno-sanitize-recover=all)
target_link_options(dspbr_lookup_nan PRIVATE -fsanitize=undefined,address)
target_link_libraries(dspbr_lookup_nan PRIVATE m)
add_dependencies(dspbr_tests dspbr_lookup_nan)
add_test(NAME lookup_nan_c COMMAND dspbr_lookup_nan)
