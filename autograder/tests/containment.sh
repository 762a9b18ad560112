#!/bin/sh
# Grades a plugin that tries to change files outside its scratch folder (a
# canary folder and its own plugin folder) and checks that nothing there
# changed: contents, names, modes and times, byte for byte.
#   containment.sh RIXGRADE PLUGIN_DIR RUBRIC OUT EXPECT_GRADE_PY
set -u
rixgrade=$1 plugins=$2 rubric=$3 out=$4 expect=$5
outside=$out-outside
rm -rf "$out" "$outside"
mkdir -p "$(dirname "$out")"
mkdir -p "$outside"
echo "precious" > "$outside/canary.txt"
echo "precious" > "$plugins/canary.txt"
snapshot() {
  for folder in "$outside" "$plugins"; do
    find "$folder" -printf '%p %s %m %T@\n' | sort
    find "$folder" -type f -exec sha256sum {} + | sort
  done
}
snapshot > "$out-before.txt"
RIXGRADE_TEST_OUTSIDE=$outside "$rixgrade" --plugins "$plugins" --rubric "$rubric" --out "$out" > "$out.log" 2>&1
status=$?
if grep -q "this kernel has no Landlock" "$out.log"; then
  echo "SKIPPED: this kernel cannot confine writes (no Landlock)"
  exit 77
fi
snapshot > "$out-after.txt"
[ $status -eq 0 ] || { echo "PROBLEM: rixgrade exited with status $status"; cat "$out.log"; exit 1; }
if ! diff "$out-before.txt" "$out-after.txt"; then
  echo "PROBLEM: files outside the grading folder changed (above: < before, > after)"
  exit 1
fi
echo "nothing outside the grading folder changed"
# The grading itself went on: the plugin is otherwise correct (the hostile
# rubric renders at 1 sample per pixel, too few for the render check).
exec /usr/bin/python3 "$expect" "$out/results.json" --pass loads --pass chi2
