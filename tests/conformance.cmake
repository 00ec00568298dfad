# CTest entry for the conformance harness (examples/conformance/, docs/conformance.md): generates a
# small vector set, drives the C harness with it (the reference BSDF as the renderer) and checks
# the results: `dspbr conformance check` must exit 0.
add_test(NAME conformance_harness
         COMMAND sh -c "rm -rf conformance-harness && \
'$<TARGET_FILE:dspbr>' conformance generate --directions 3 --no-albedo --out conformance-harness > /dev/null && \
'$<TARGET_FILE:example_conformance>' conformance-harness/vectors.csv conformance-harness/results.csv && \
'$<TARGET_FILE:dspbr>' conformance check conformance-harness/vectors.json conformance-harness/results.csv --no-html \
--out conformance-harness/report"
         WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
set_tests_properties(conformance_harness PROPERTIES TIMEOUT 120)
# The batched harness (renderer_eval_batch: one call per material) on its own small set: `check`
# exits 0 and the results file is the per-vector harness's, byte for byte.
add_test(NAME conformance_harness_batch
         COMMAND sh -c "rm -rf conformance-batch && \
'$<TARGET_FILE:dspbr>' conformance generate --directions 3 --no-albedo --out conformance-batch > /dev/null && \
'$<TARGET_FILE:example_conformance_batch>' conformance-batch/vectors.csv conformance-batch/results.csv && \
'$<TARGET_FILE:dspbr>' conformance check conformance-batch/vectors.json conformance-batch/results.csv --no-html \
--out conformance-batch/report && \
'$<TARGET_FILE:example_conformance>' conformance-batch/vectors.csv conformance-batch/one-by-one.csv && \
cmp conformance-batch/results.csv conformance-batch/one-by-one.csv"
         WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
set_tests_properties(conformance_harness_batch PROPERTIES TIMEOUT 120)
