# CTest entry for the quick validation run (`dspbr validate --quick`): every check on every DSPBR
# component at reduced sample counts, plus the HTML report (scripts/report/make_report.py).
# Fails when a check fails or the report cannot be made.
add_test(NAME validate_quick
         COMMAND dspbr validate --quick --out ${PROJECT_BINARY_DIR}/validate-quick)
set_tests_properties(validate_quick PROPERTIES TIMEOUT 600)
