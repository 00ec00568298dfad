# CTest entry for `dspbr fit --quick` (small grids, ~3 s): runs every fit with 1 and with 2
# threads and requires byte-identical outputs (JSON and generated header).
add_test(NAME fit_quick_deterministic
         COMMAND sh -c "rm -rf fit-q1 fit-q2 && \
'$<TARGET_FILE:dspbr>' fit --quick --threads 1 --out fit-q1 > /dev/null && \
'$<TARGET_FILE:dspbr>' fit --quick --threads 2 --out fit-q2 > /dev/null && \
diff -r fit-q1 fit-q2"
         WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
set_tests_properties(fit_quick_deterministic PROPERTIES TIMEOUT 300)
