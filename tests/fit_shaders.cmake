# The generated fit shaders (fits/dspbr_fits.glsl, .hlsl; fit/fits_shader.h) compile with
# glslangValidator (Debian glslang-tools). Numbers: tests/test_fit_shaders.cpp.
find_program(DSPBR_GLSLANG_FITS glslangValidator)
if(DSPBR_GLSLANG_FITS)
  add_test(NAME fits_glsl
           COMMAND ${DSPBR_GLSLANG_FITS} -V -I${PROJECT_SOURCE_DIR}/fits -o ${CMAKE_CURRENT_BINARY_DIR}/fits_glsl.spv
                   ${CMAKE_CURRENT_LIST_DIR}/shaders/fits_test.frag)
  add_test(NAME fits_hlsl
           COMMAND ${DSPBR_GLSLANG_FITS} -D -V -S frag -e main -I${PROJECT_SOURCE_DIR}/fits
                   -o ${CMAKE_CURRENT_BINARY_DIR}/fits_hlsl.spv ${CMAKE_CURRENT_LIST_DIR}/shaders/fits_test.hlsl)
endif()
