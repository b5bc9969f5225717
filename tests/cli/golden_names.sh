#!/usr/bin/env bash
# The golden cases are listed by name (PrintTo), not by a hex dump of their parameter, and
# no case is instantiated only to be skipped (a check-mode case has no streamed run).
set -u
golden=$1
list=$("$golden" --gtest_list_tests) || { echo "FAIL: --gtest_list_tests"; exit 1; }
echo "$list" | grep -q 'byte object' && { echo "FAIL: a parameter printed as bytes"; exit 1; }
echo "$list" | grep -qE '^  Run/check_w001_dpi  # GetParam\(\) = check_w001_dpi$' || { echo "FAIL: name not printed"; exit 1; }
echo "$list" | grep -q '^  RunIsTheSame/check_w001_dpi ' && { echo "FAIL: a check-mode case has a streamed run (skipped)"; exit 1; }
"$golden" --gtest_filter='All/Golden*.*check_*' 2>&1 | grep -q '\[  SKIPPED \]' &&
  { echo "FAIL: a golden test is skipped"; exit 1; }
echo ok
