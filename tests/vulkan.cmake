# The Vulkan programs, on the Vulkan plumbing of src/dspbr/vulkan/vk_compute.h (one compute shader,
# its buffers and the lookup tables as textures; library dspbr_vulkan):
# 1. The generated GLSL lookups and fits on a real Vulkan driver (tests/vulkan/vulkan_lookup.cpp):
# tests/shaders/vulkan_lookup.comp compiled to SPIR-V by glslangValidator in texture mode (the
# tables uploaded from the committed luts/renderer/*.exr as R32F images, bound as the headers
# say), run on the first Vulkan device (Mesa's lavapipe here: Debian mesa-vulkan-drivers,
# libvulkan-dev) and compared with the C header and the C++ fits at 4096 points. Without a device
# the program exits 77 and CTest reports the test skipped; without Vulkan headers or
# glslangValidator the entry is disabled (reported "Not Run").
# The constant-array mode runs in part (CTest vulkan_lookup_arrays_1d, the shader built with
# VULKAN_LOOKUP_1D): the outputs that read no table or only the 1-D tables (ggx_E_avg, its
# missing part, base_E_avg, fresnel_ms, the fits), the others must come back 0. Lavapipe cannot
# run more in CI time: a shader indexing one 2-D constant table (GGX_E, 2048 floats) took over
# 100 s to create its pipeline (67 s with the tables as private variables instead of constants),
# the whole set over 300 s (measured 2026-12-04 on this project's 2-core machine). The rest of
# that mode is the compile check lookup_glsl_arrays (tests/lookup_code.cmake).
# 2. The renderer-side example (examples/vulkan/sphere.cpp, CTest vulkan_sphere_example): a sphere
# per material of the validation scenes shaded by examples/vulkan/sphere.comp with the shader
# library (dspbr.glsl, the tables as textures), written to build/vulkan_sphere.exr and compared
# with the C++ reference BSDF.
find_package(Vulkan QUIET)
find_program(DSPBR_GLSLANG_VK glslangValidator)
set(_vk_tests vulkan_lookup_textures vulkan_lookup_arrays_1d vulkan_sphere_example)
if(Vulkan_FOUND AND DSPBR_GLSLANG_VK)
  set(_vk_dir ${PROJECT_SOURCE_DIR}/examples/vulkan)
  add_executable(vulkan_lookup ${CMAKE_CURRENT_LIST_DIR}/vulkan/vulkan_lookup.cpp)
  target_include_directories(vulkan_lookup PRIVATE ${PROJECT_SOURCE_DIR}/luts ${PROJECT_SOURCE_DIR}/fits)
  target_link_libraries(vulkan_lookup PRIVATE dspbr_vulkan)
  target_compile_options(vulkan_lookup PRIVATE -Wall -Wextra)
  set(_spv_files "")
  foreach(mode textures arrays-1d)
    set(_def "-DDSPBR_LOOKUP_TEXTURES")
    if(mode STREQUAL "arrays-1d")
      set(_def "-DVULKAN_LOOKUP_1D")
    endif()
    set(_spv ${PROJECT_BINARY_DIR}/vulkan_lookup_${mode}.spv)
    add_custom_command(OUTPUT ${_spv}
      COMMAND ${DSPBR_GLSLANG_VK} -V ${_def} -I${PROJECT_SOURCE_DIR}/luts -I${PROJECT_SOURCE_DIR}/fits -o ${_spv}
              ${CMAKE_CURRENT_LIST_DIR}/shaders/vulkan_lookup.comp
      DEPENDS ${CMAKE_CURRENT_LIST_DIR}/shaders/vulkan_lookup.comp ${PROJECT_SOURCE_DIR}/luts/dspbr_lookup.glsl
              ${PROJECT_SOURCE_DIR}/luts/dspbr_glass_lookup.glsl ${PROJECT_SOURCE_DIR}/fits/dspbr_fits.glsl
      COMMENT "glslangValidator: vulkan_lookup.comp (${mode})" VERBATIM)
    list(APPEND _spv_files ${_spv})
  endforeach()
  add_custom_target(vulkan_lookup_shaders ALL DEPENDS ${_spv_files})
  add_dependencies(vulkan_lookup vulkan_lookup_shaders)
  add_test(NAME vulkan_lookup_textures
           COMMAND vulkan_lookup ${PROJECT_BINARY_DIR}/vulkan_lookup_textures.spv textures ${PROJECT_SOURCE_DIR}/luts)
  add_test(NAME vulkan_lookup_arrays_1d COMMAND vulkan_lookup ${PROJECT_BINARY_DIR}/vulkan_lookup_arrays-1d.spv arrays-1d)
  set_tests_properties(vulkan_lookup_textures vulkan_lookup_arrays_1d PROPERTIES TIMEOUT 300)

  set(_spv ${PROJECT_BINARY_DIR}/vulkan_sphere.spv)
  file(GLOB _sphere_deps ${PROJECT_SOURCE_DIR}/shaders/*.* ${PROJECT_SOURCE_DIR}/shaders/dspbr/*)
  add_custom_command(OUTPUT ${_spv}
    COMMAND ${DSPBR_GLSLANG_VK} -V -I${PROJECT_SOURCE_DIR}/shaders -I${PROJECT_SOURCE_DIR}/luts -o ${_spv}
            ${_vk_dir}/sphere.comp
    DEPENDS ${_vk_dir}/sphere.comp ${_sphere_deps} ${PROJECT_SOURCE_DIR}/luts/dspbr_lookup.glsl
    COMMENT "glslangValidator: sphere.comp" VERBATIM)
  add_custom_target(vulkan_sphere_shader ALL DEPENDS ${_spv})
  add_executable(example_vulkan_sphere ${_vk_dir}/sphere.cpp ${_vk_dir}/sphere_scene.cpp)
  add_dependencies(example_vulkan_sphere vulkan_sphere_shader)
  target_link_libraries(example_vulkan_sphere PRIVATE dspbr_vulkan dspbr_shader_host dspbr_formats PkgConfig::OIIO
                                                      nlohmann_json::nlohmann_json)
  target_compile_options(example_vulkan_sphere PRIVATE -Wall -Wextra)
  add_test(NAME vulkan_sphere_example
           COMMAND example_vulkan_sphere ${_spv} ${PROJECT_SOURCE_DIR}/luts ${PROJECT_SOURCE_DIR}/data/dspbr/scenes/sphere
                   ${PROJECT_BINARY_DIR}/vulkan_sphere.exr)
  set_tests_properties(vulkan_sphere_example PROPERTIES TIMEOUT 120)
  # 77: no Vulkan device (reported skipped); the driver's runtime folder inside the build tree.
  set_tests_properties(${_vk_tests} PROPERTIES SKIP_RETURN_CODE 77 ENVIRONMENT "XDG_RUNTIME_DIR=${PROJECT_BINARY_DIR}")
else()
  message(STATUS "Vulkan tests disabled: need libvulkan-dev and glslangValidator (Debian packages)")
  foreach(_name ${_vk_tests})
    add_test(NAME ${_name} COMMAND ${CMAKE_COMMAND} -E echo "Vulkan or glslangValidator not found")
    set_tests_properties(${_name} PROPERTIES DISABLED TRUE)
  endforeach()
endif()
