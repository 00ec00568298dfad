# The shader library (shaders/, docs/renderer.md): the DSPBR BSDF as one GLSL-style source that
# compiles as C++17 (shaders/dspbr.h), GLSL 450 (dspbr.glsl) and HLSL (dspbr.hlsl), over the
# generated lookups of luts/ (or, with DSPBR_USE_FITS, the fits of fits/). Header-only: the CMake
# target dspbr::shaders (INTERFACE) gives C++ consumers its include folders; installed to
# <prefix>/share/dspbr/shaders (the body, the entries, the lookup and the fit files together, so
# one include folder serves every language and mode) and exported as the package component
# `shaders` (find_package(dspbr COMPONENTS shaders)).
add_library(dspbr_shaders INTERFACE)
add_library(dspbr::shaders ALIAS dspbr_shaders)
set_target_properties(dspbr_shaders PROPERTIES EXPORT_NAME shaders)
target_include_directories(dspbr_shaders INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/shaders>
                                                   $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/luts>
                                                   $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/fits>
                                                   $<INSTALL_INTERFACE:${CMAKE_INSTALL_DATADIR}/dspbr/shaders>)
target_compile_features(dspbr_shaders INTERFACE cxx_std_17)
if(DSPBR_INSTALL)
  set(_dspbr_shader_dir ${CMAKE_INSTALL_DATADIR}/dspbr/shaders)
  install(TARGETS dspbr_shaders EXPORT dspbr_shadersTargets)
  install(EXPORT dspbr_shadersTargets NAMESPACE dspbr:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/dspbr)
  # The generated lookups and fits beside the entries: DSPBR_SHADER_LOOKUPS (CMakeLists.txt).
  install(FILES ${PROJECT_SOURCE_DIR}/shaders/dspbr.h ${PROJECT_SOURCE_DIR}/shaders/dspbr.glsl
                ${PROJECT_SOURCE_DIR}/shaders/dspbr.hlsl ${PROJECT_SOURCE_DIR}/shaders/README.md
                ${DSPBR_SHADER_LOOKUPS}
          DESTINATION ${_dspbr_shader_dir})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/dspbr ${PROJECT_SOURCE_DIR}/shaders/conformance
          DESTINATION ${_dspbr_shader_dir})
endif()
