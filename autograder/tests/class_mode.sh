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
# Solving the diffuse exercise earns its 12 remaining points (both already earn 'loads').
python3 -c "import sys; a, b = float('$alice'), float('$bob'); sys.exit(0 if b - a == 12 else 1)" || { echo "unexpected totals: alice $alice, bob $bob"; exit 1; }
echo "class graded: alice $alice, bob $bob"
