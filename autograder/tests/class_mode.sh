#!/bin/sh
# Grades a class of two submissions made from the starter: "alice" untouched,
# "bob" with the diffuse exercise solved. Checks the gradebook's totals.
set -e
root=$1 out=$2 rixgrade=$3
rm -rf "$out" && mkdir -p "$out/class"
cp -r "$root/starter" "$out/class/alice"
cp -r "$root/starter" "$out/class/bob"
cp "$root/solutions/ch06/diffuse/Diffuse.cpp" "$out/class/bob/ch06/diffuse/Diffuse.cpp"
"$rixgrade" --class "$out/class" --jobs 2 --chapter 6 --out "$out/grades" > "$out/log.txt" 2>&1
cat "$out/grades/gradebook.csv"
alice=$(grep '^alice,' "$out/grades/gradebook.csv" | cut -d, -f2)
bob=$(grep '^bob,' "$out/grades/gradebook.csv" | cut -d, -f2)
test -f "$out/grades/alice/report.html" && test -f "$out/grades/bob/results.json"
# Solving diffuse earns all its points except "loads", which the untouched starter already has.
python3 - "$root/autograder/rubric.json" "$alice" "$bob" <<'EOF' || { echo "unexpected totals: alice $alice, bob $bob"; exit 1; }
import json, sys
checks = json.load(open(sys.argv[1]))["chapters"]["6"]["diffuse"]["checks"]
gain = sum(checks.values()) - checks["loads"]
sys.exit(0 if float(sys.argv[3]) - float(sys.argv[2]) == gain else 1)
EOF
echo "class graded: alice $alice, bob $bob"
