#!/usr/bin/env bash
# Fuzz corpus for `lituya pre` (issue 9, item 6). A deterministic generator corrupts the example
# scenes (examples/case_a_2d, examples/case_b_2d), their .geo scripts and a small .msh
# (cli/tests/fuzz/case_b.msh, case_b.geo meshed once by gmsh 4.x with -clmax 0.12) in several
# hundred ways: wrong types, out-of-range numbers, deleted and duplicated lines, truncation,
# garbage bytes, odd names, missing files, unknown keys, broken geometry and meshes.
# `lituya pre SCENE -o OUT --force` must either accept each case (exit 0, OUT written) or refuse
# it (exit 1, with a message on stderr that names a .toml, .geo or .msh file). Anything else -
# a crash (exit >= 128), a time-out (20 s per case) or another exit code - is a failure.
#
# usage: fuzz_pre.sh LITUYA SOURCE_DIR WORK_DIR [JOBS]
#   LITUYA      the built binary; SOURCE_DIR the repository root; WORK_DIR a scratch folder
#               (emptied first); JOBS parallel cases (default 2).
# The corpus is the same on every run: mutations are a fixed list, and choices among them come
# from a linear congruential generator with a fixed seed. Cases are numbered; a failing case
# is printed with its description and output, and its folder is kept in WORK_DIR.
set -u
export LC_ALL=C

# --- one case: run by the parallel workers (fuzz_pre.sh --check LITUYA CASE_DIR) -------------
if [ "${1:-}" = "--check" ]; then
  lituya=$2
  dir=$3
  cd "$dir" || exit 1
  timeout 20 "$lituya" pre scene.toml -o out --force >stdout.txt 2>stderr.txt
  code=$?
  verdict=""
  if [ "$code" -eq 0 ]; then
    if [ ! -f out/stages.toml ]; then verdict="exit 0 but no case folder written (out/stages.toml)"; fi
  elif [ "$code" -eq 1 ]; then
    # The file named: a scene, geometry or mesh, or the one a case names in expect.txt.
    pattern='[^[:space:]]*\.(toml|geo|msh)'
    [ -f expect.txt ] && pattern="$pattern|$(cat expect.txt)"
    if ! grep -Eq "$pattern" stderr.txt; then
      verdict="exit 1 without a file name on stderr"
    fi
  elif [ "$code" -eq 124 ]; then
    verdict="timed out after 20 s"
  elif [ "$code" -ge 128 ]; then
    verdict="crashed (exit $code, signal $((code - 128)))"
  else
    verdict="unexpected exit code $code"
  fi
  echo "$code" >code.txt
  if [ -n "$verdict" ]; then
    {
      echo "FAIL $(basename "$dir"): $(cat case.txt)"
      echo "  $verdict"
      echo "  --- stdout:"; sed 's/^/  /' stdout.txt | head -20
      echo "  --- stderr:"; sed 's/^/  /' stderr.txt | head -20
    } >fail.txt
    cat fail.txt
    exit 1
  fi
  rm -rf out  # keep the scratch folder small
  exit 0
fi

if [ $# -lt 3 ]; then
  echo "usage: fuzz_pre.sh LITUYA SOURCE_DIR WORK_DIR [JOBS]" >&2
  exit 2
fi
LITUYA=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SRC=$(cd "$2" && pwd)
WORK=$3
JOBS=${4:-2}
SELF=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
rm -rf "$WORK"
mkdir -p "$WORK/base" || exit 2
WORK=$(cd "$WORK" && pwd)

# --- base inputs: copies of the examples with coarse meshes (fast) ---------------------------
B=$WORK/base
mkdir -p "$B/b" "$B/a" "$B/m"
cp "$SRC/examples/case_b_2d/scene.toml" "$SRC/examples/case_b_2d/case_b.geo" "$B/b/"
sed -i 's/^cell_size = [0-9.e-]*/cell_size = 0.05/' "$B/b/scene.toml"
cp "$SRC/examples/case_a_2d/scene.toml" "$SRC/examples/case_a_2d/case_a.geo" \
  "$SRC/examples/case_a_2d/reference.csv" "$B/a/"
sed -i 's/^cell_size = [0-9.e-]*/cell_size = 0.03/' "$B/a/scene.toml"
cp "$B/b/scene.toml" "$B/m/scene.toml"
sed -i 's/^geometry = "case_b.geo"/geometry = "case_b.msh"/' "$B/m/scene.toml"
cp "$SRC/cli/tests/fuzz/case_b.msh" "$B/m/"
for base in a b m; do
  if ! (cd "$B/$base" && "$LITUYA" pre scene.toml -o out --force >/dev/null 2>&1); then
    echo "base scene '$base' is not accepted by lituya pre: the corpus needs valid bases" >&2
    (cd "$B/$base" && "$LITUYA" pre scene.toml -o out --force)
    exit 1
  fi
  rm -rf "$B/$base/out"
done

# --- generator helpers ------------------------------------------------------------------------
seed=20260911
rand() {  # rand N: sets R to a deterministic number in [0, N)
  seed=$(((seed * 1103515245 + 12345) % 2147483648))
  R=$(((seed / 65536) % $1))
}
n=0
CASE=""
new() {  # new BASE DESCRIPTION: a fresh case folder with a copy of base BASE (a, b or m)
  n=$((n + 1))
  CASE=$WORK/$(printf 'c%04d' "$n")
  mkdir -p "$CASE"
  cp "$B/$1"/* "$CASE/"
  printf '[%s] %s\n' "$1" "$2" >"$CASE/case.txt"
}
geo_of() { case $1 in a) echo case_a.geo ;; b) echo case_b.geo ;; m) echo case_b.msh ;; esac; }
set_line() {  # set_line FILE LINE TEXT: replaces line LINE of FILE with TEXT (verbatim)
  T="$3" awk -v l="$2" 'NR == l { print ENVIRON["T"]; next } { print }' "$1" >"$1.tmp" &&
    mv "$1.tmp" "$1"
}
del_line() { awk -v l="$2" 'NR != l' "$1" >"$1.tmp" && mv "$1.tmp" "$1"; }
dup_line() { awk -v l="$2" '{ print } NR == l { print }' "$1" >"$1.tmp" && mv "$1.tmp" "$1"; }
ins_line() {  # ins_line FILE LINE TEXT: inserts TEXT after line LINE (0: at the top)
  T="$3" awk -v l="$2" 'l == 0 && NR == 1 { print ENVIRON["T"] } { print }
    NR == l && l > 0 { print ENVIRON["T"] }' "$1" >"$1.tmp" && mv "$1.tmp" "$1"
}
truncate_at() { head -c "$2" "$1" >"$1.tmp" && mv "$1.tmp" "$1"; }
garbage_at() {  # garbage_at FILE OFFSET: inserts bytes no text file should hold
  { head -c "$2" "$1"; printf '\000\377\376\x1b[0m\r\n\x80\xc3('; tail -c +"$(($2 + 1))" "$1"; } \
    >"$1.tmp" && mv "$1.tmp" "$1"
}
size_of() { wc -c <"$1" | tr -d ' '; }
lines_of() { wc -l <"$1" | tr -d ' '; }

# Values that no key should take without a clean message: types and ranges.
values=('"text"' '[1.0, 2.0]' '-1.0' '0' '1e308' '-1e308' 'nan' 'inf' '-inf' 'true' '{}'
  '[]' '1e-308' '-0.0' '2147483648' '9223372036854775807' '-9223372036854775808'
  '1970-01-01T00:00:00Z' '"1.0"' '[["a"], [1]]' '0.5' '3' '1e999' '')
nv=${#values[@]}
# Odd names, for the keys that hold names (material, stage, group, title, geometry, file names).
names=('""' '".."' '"a/b"' "\"$(printf 'x%.0s' $(seq 1 300))\"" '"béads"' '"a\nb"'
  '"../../../etc/passwd"' '"-x"' '".hidden"' '"a b"' '"\u0000"' '"CON"' '"*"' '"\t"'
  "'literal'" '"""multi\nline"""' '"/"' '"."')

# --- TOML: every key line of each scene -----------------------------------------------------
for base in b a m; do
  scene=$B/$base/scene.toml
  # Base m is base b with a .msh: its keys and syntax are only mutated through base b.
  [ "$base" = m ] && mutate_keys=no || mutate_keys=yes
  while IFS=: read -r line text; do
    [ "$mutate_keys" = yes ] || break
    key=${text%% *}
    # Wrong types and out-of-range values: 3 per key (b), 2 per key (a), chosen by the LCG.
    picks=3
    [ "$base" != b ] && picks=2
    for ((k = 0; k < picks; k++)); do
      rand "$nv"
      v=${values[$R]}
      new "$base" "scene.toml:$line: $key = $v"
      set_line "$CASE/scene.toml" "$line" "$key = $v"
    done
    new "$base" "scene.toml:$line: line deleted ($key)"
    del_line "$CASE/scene.toml" "$line"
    if [ "$base" = b ]; then
      new "$base" "scene.toml:$line: line duplicated ($key)"
      dup_line "$CASE/scene.toml" "$line"
    fi
    case $key in
      name | group | material | title | geometry | reference | stage | type | model | \
        initial_stress | format)
        picks=2
        [ "$base" != b ] && picks=1
        for ((k = 0; k < picks; k++)); do
          rand "${#names[@]}"
          new "$base" "scene.toml:$line: $key = ${names[$R]}"
          set_line "$CASE/scene.toml" "$line" "$key = ${names[$R]}"
        done
        ;;
    esac
  done < <(grep -n '^[A-Za-z_][A-Za-z0-9_]* *= ' "$scene")

  # Unknown keys, tables and syntax, after each table header (b) or a few (a, m).
  while IFS=: read -r line text; do
    [ "$mutate_keys" = yes ] || break
    new "$base" "scene.toml: unknown key after $text (line $line)"
    ins_line "$CASE/scene.toml" "$line" "cohesoin = 1.0"
    if [ "$base" = b ]; then
      new "$base" "scene.toml: bad syntax after $text (line $line)"
      ins_line "$CASE/scene.toml" "$line" "key = = [1, 2"
      new "$base" "scene.toml: table header duplicated: $text (line $line)"
      ins_line "$CASE/scene.toml" "$line" "$text"
    fi
  done < <(grep -n '^\[' "$scene")
  for text in '[unknown_table]' '[[mesh]]' '[mesh.sub]' 'mesh = 3' '[[stage]]' '[[material]]' \
    '[[region]]' '[[boundary]]' '[output]' '[post]' 'gravity = [0.0]' 'gravity = [0.0, -9.81, 0.0]' \
    'x.y.z = 1' '"quoted key" = 1' '= 1' 'a = 1 b = 2' '[' ']]' '#' "$(printf '\xef\xbb\xbfkey = 1')"; do
    [ "$mutate_keys" = yes ] || break
    new "$base" "scene.toml: appended '$text'"
    printf '%s\n' "$text" >>"$CASE/scene.toml"
    new "$base" "scene.toml: prepended '$text'"
    ins_line "$CASE/scene.toml" 0 "$text"
  done

  # Truncation at several byte counts, and garbage bytes.
  size=$(size_of "$scene")
  for frac in 0 1 3 7 13 29 50 71 89 97 99; do
    cut=$((size * frac / 100))
    new "$base" "scene.toml truncated at $cut of $size bytes"
    truncate_at "$CASE/scene.toml" "$cut"
  done
  for ((k = 0; k < 8; k++)); do
    rand "$size"
    new "$base" "scene.toml: garbage bytes at offset $R"
    garbage_at "$CASE/scene.toml" "$R"
  done

  # Missing and odd files.
  g=$(geo_of "$base")
  new "$base" "geometry file $g missing (renamed away)"
  mv "$CASE/$g" "$CASE/$g.away"
  new "$base" "geometry file $g is a folder"
  rm "$CASE/$g" && mkdir "$CASE/$g"
  new "$base" "geometry file $g is empty"
  : >"$CASE/$g"
  new "$base" "geometry file $g is unreadable binary"
  head -c 4096 /dev/zero | tr '\0' '\377' >"$CASE/$g"
  new "$base" "geometry file $g is a dangling symbolic link"
  rm "$CASE/$g" && ln -s nowhere/at/all "$CASE/$g"
  new "$base" "geometry file $g is a symbolic link to itself"
  rm "$CASE/$g" && ln -s "$g" "$CASE/$g"
  new "$base" "scene.toml missing"
  rm "$CASE/scene.toml"
  new "$base" "scene.toml is a folder"
  rm "$CASE/scene.toml" && mkdir "$CASE/scene.toml"
  new "$base" "scene.toml is empty"
  : >"$CASE/scene.toml"
  new "$base" "scene.toml is a single newline"
  echo >"$CASE/scene.toml"
  new "$base" "scene.toml has CRLF line ends"
  sed -i 's/$/\r/' "$CASE/scene.toml"
  new "$base" "scene.toml is UTF-16"
  printf '\xff\xfe' >"$CASE/scene.toml.tmp"
  sed 's/./&\x00/g' "$B/$base/scene.toml" >>"$CASE/scene.toml.tmp"
  mv "$CASE/scene.toml.tmp" "$CASE/scene.toml"
  for other in 'case_a.geo' 'scene.toml' 'reference.csv' '/dev/null' '/dev/zero' '/proc/self/mem' \
    '/' 'case_b.GEO' 'case_b' 'case_b.step' 'nonexistent.msh' 'missing/dir/x.geo'; do
    new "$base" "geometry = \"$other\""
    sed -i "s|^geometry = .*|geometry = \"$other\"|" "$CASE/scene.toml"
  done
  # The output folder is in the way: a file, or -o names the scene's own folder are handled by
  # the CLI tests; here an existing file named out.
  new "$base" "a file named 'out' where the case folder goes"
  echo x >"$CASE/out"
  echo 'out:' >"$CASE/expect.txt"
  new "$base" "'out' is a symbolic link to itself"
  ln -s out "$CASE/out"
  echo 'out' >"$CASE/expect.txt"
  new "$base" "scene.toml is a symbolic link to itself"
  rm "$CASE/scene.toml" && ln -s scene.toml "$CASE/scene.toml"
  new "$base" "scene.toml is a dangling symbolic link"
  rm "$CASE/scene.toml" && ln -s nowhere/scene.toml "$CASE/scene.toml"
done
# case_a's [post] reference file.
new a "reference.csv missing"
rm "$CASE/reference.csv"
new a "reference.csv empty"
: >"$CASE/reference.csv"
new a "reference.csv garbage"
printf '\000\001\002,,,\n1,2\nx,y,z,w\n' >"$CASE/reference.csv"

# --- .geo scripts ---------------------------------------------------------------------------
for base in b a; do
  g=$(geo_of "$base")
  geo=$B/$base/$g
  size=$(size_of "$geo")
  nl=$(lines_of "$geo")
  for frac in 1 5 10 20 30 40 50 60 70 80 90 95 98 99; do
    cut=$((size * frac / 100))
    new "$base" "$g truncated at $cut of $size bytes"
    truncate_at "$CASE/$g" "$cut"
  done
  for ((k = 0; k < 25; k++)); do
    rand "$nl"
    l=$((R + 1))
    new "$base" "$g:$l: line deleted: $(sed -n "${l}p" "$geo" | cut -c1-60)"
    del_line "$CASE/$g" "$l"
  done
  for ((k = 0; k < 6; k++)); do
    rand "$nl"
    l=$((R + 1))
    new "$base" "$g:$l: line duplicated"
    dup_line "$CASE/$g" "$l"
  done
  # Numbers turned into garbage: the k-th number of the script, for a few k.
  nnum=$(grep -o '[0-9][0-9.]*' "$geo" | wc -l)
  garbage=('x' '1e999' '-' '1..2' 'nan' '0/0' '{' '"s"' '1e-320' '99999999999999999999')
  for ((k = 0; k < 20; k++)); do
    rand "$nnum"
    which=$((R + 1))
    rand "${#garbage[@]}"
    gv=${garbage[$R]}
    new "$base" "$g: number $which of $nnum replaced by '$gv'"
    G="$gv" awk -v w="$which" '{
        out = ""; s = $0
        while (match(s, /[0-9][0-9.]*/)) {
          c++
          rep = (c == w) ? ENVIRON["G"] : substr(s, RSTART, RLENGTH)
          out = out substr(s, 1, RSTART - 1) rep; s = substr(s, RSTART + RLENGTH)
        }
        print out s }' "$geo" >"$CASE/$g"
  done
  for ((k = 0; k < 6; k++)); do
    rand "$size"
    new "$base" "$g: garbage bytes at offset $R"
    garbage_at "$CASE/$g" "$R"
  done
  # Meshing options and broken geometry.
  for text in 'Mesh.Algorithm = 8;' 'Mesh.Algorithm = 9;' 'Mesh.Algorithm = 11;' \
    'Mesh.Algorithm3D = 9;' 'MeshAlgorithm Surface {1} = 8;' 'Mesh.RecombineAll = 1;' \
    'Recombine Surface {1};' 'Mesh.ElementOrder = 2;' 'Mesh.SubdivisionAlgorithm = 1;' \
    'Mesh.MeshSizeMax = 1e-9;' 'Mesh.MeshSizeMin = 10;' 'Mesh.MeshSizeFactor = 0;' \
    'Mesh.Algorithm = -1;' 'Mesh.Algorithm = 1e308;' 'Mesh.Format = 2;' 'Geometry.Tolerance = 1e308;' \
    'Include "missing.geo";' 'Include "scene.toml";' 'Merge "missing.msh";' 'Error("fuzz");' \
    'Printf("fuzz %g", 1);' 'x[] = {1,2}; y = x[7];' 'Point(1) = {0, 0, 0};' \
    'Point(100) = {nan, 0, 0};' 'Line(1) = {1, 999};' 'Plane Surface(50) = {77};' \
    'Physical Surface("water") = {999};' 'Physical Curve("") = {1};' 'Physical Surface(1) = {1};' \
    'Physical Point("corner") = {1};' 'Physical Volume("vol") = {1};' \
    'Extrude {0, 0, 1} { Surface{1}; }' 'Delete { Surface{1}; }' 'Coherence;' \
    'Transfinite Surface {1};' 'Periodic Curve {1} = {2};' 'Point(101) = {1e308, 1e308, 0};' \
    'Rotate {{0,0,1},{0,0,0},Pi/3} { Surface{1}; }' 'Translate {1e300, 0, 0} { Surface{1}; }' \
    'Dilate {{0,0,0}, 0} { Surface{1}; }' 'SetFactory("OpenCASCADE");' 'Mesh 3;' 'Mesh 1;' \
    '{' '}' '/*' '"' 'Printf(' 'For i In {1:3}' 'If (1)' 'EndFor' 'Exit;' 'Abort;'; do
    new "$base" "$g: appended '$text'"
    printf '\n%s\n' "$text" >>"$CASE/$g"
  done
  # An open curve loop: the last curve of each loop dropped, and a curve of it reversed.
  while IFS=: read -r line text; do
    new "$base" "$g:$line: curve loop opened: $text"
    set_line "$CASE/$g" "$line" "$(echo "$text" | sed -E 's/, *-?[0-9]+\};/};/')"
    new "$base" "$g:$line: curve loop with a reversed curve: $text"
    set_line "$CASE/$g" "$line" "$(echo "$text" | sed -E 's/\{ *(-?)([0-9]+)/{-\1\2/; s/\{--/{/')"
  done < <(grep -n '^Curve Loop' "$geo")
  new "$base" "$g: every Physical line deleted"
  sed -i '/^Physical/d' "$CASE/$g"
  new "$base" "$g: CRLF line ends"
  sed -i 's/$/\r/' "$CASE/$g"
done

# --- .msh -----------------------------------------------------------------------------------
msh=$B/m/case_b.msh
size=$(size_of "$msh")
nl=$(lines_of "$msh")
for frac in 1 2 5 10 20 30 40 50 60 70 80 90 95 99; do
  cut=$((size * frac / 100))
  new m "case_b.msh truncated at $cut of $size bytes"
  truncate_at "$CASE/case_b.msh" "$cut"
done
for ((k = 0; k < 30; k++)); do
  rand "$nl"
  l=$((R + 1))
  new m "case_b.msh:$l: line deleted: $(sed -n "${l}p" "$msh" | cut -c1-60)"
  del_line "$CASE/case_b.msh" "$l"
done
for ((k = 0; k < 6; k++)); do
  rand "$nl"
  l=$((R + 1))
  new m "case_b.msh:$l: line duplicated"
  dup_line "$CASE/case_b.msh" "$l"
done
for ((k = 0; k < 8; k++)); do
  rand "$size"
  new m "case_b.msh: garbage bytes at offset $R"
  garbage_at "$CASE/case_b.msh" "$R"
done
# Field edits inside each section: a line of the section, one of its numbers replaced.
mgarbage=('-1' '0' '99999' '2147483648' 'nan' 'inf' '1e308' 'x' '3' '15' '-0' '1.5')
for section in MeshFormat PhysicalNames Entities Nodes Elements; do
  first=$(grep -n "^\\\$$section\$" "$msh" | cut -d: -f1)
  last=$(grep -n "^\\\$End$section\$" "$msh" | cut -d: -f1)
  span=$((last - first - 1))
  for ((k = 0; k < 8; k++)); do
    rand "$span"
    l=$((first + 1 + R))
    nf=$(sed -n "${l}p" "$msh" | awk '{ print NF }')
    [ "$nf" -gt 0 ] || nf=1
    rand "$nf"
    f=$((R + 1))
    rand "${#mgarbage[@]}"
    mv_=${mgarbage[$R]}
    new m "case_b.msh:$l: field $f of \$$section set to '$mv_'"
    M="$mv_" awk -v l="$l" -v f="$f" 'NR == l { $f = ENVIRON["M"] } { print }' "$msh" \
      >"$CASE/case_b.msh"
  done
  new m "case_b.msh: section \$$section deleted"
  awk -v a="$first" -v b="$last" 'NR < a || NR > b' "$msh" >"$CASE/case_b.msh"
  new m "case_b.msh: section \$$section duplicated"
  { cat "$msh"; sed -n "${first},${last}p" "$msh"; } >"$CASE/case_b.msh"
done
for version in '2.2 0 8' '4.0 0 8' '4.1 1 8' '4.1 0 4' '9.9 0 8' '1 0 8' '-4.1 0 8' 'x'; do
  new m "case_b.msh: format line '$version'"
  set_line "$CASE/case_b.msh" 2 "$version"
done
new m "case_b.msh: all triangles made quadrangles (type 3)"
awk '/^\$Elements/ { e = 1 } /^\$EndElements/ { e = 0 }
  e && NF == 4 && $1 == 2 { $3 = 3 } { print }' "$msh" >"$CASE/case_b.msh"
new m "case_b.msh: all triangles made second-order (type 9)"
awk '/^\$Elements/ { e = 1 } /^\$EndElements/ { e = 0 }
  e && NF == 4 && $1 == 2 { $3 = 9 } { print }' "$msh" >"$CASE/case_b.msh"
new m "case_b.msh: every node at the origin"
awk '/^\$Nodes/ { s = 1 } /^\$EndNodes/ { s = 0 } s && NF == 3 && $0 ~ /\./ { $1 = 0; $2 = 0 }
  { print }' "$msh" >"$CASE/case_b.msh"
new m "case_b.msh: the y coordinates mirrored (inverted triangles)"
awk '/^\$Nodes/ { s = 1 } /^\$EndNodes/ { s = 0 } s && NF == 3 && $0 ~ /\./ { $2 = -$2 }
  { print }' "$msh" >"$CASE/case_b.msh"
new m "case_b.msh: CRLF line ends"
sed -i 's/$/\r/' "$CASE/case_b.msh"
new m "case_b.msh: a .geo script under a .msh name"
cp "$B/b/case_b.geo" "$CASE/case_b.msh"
new m "case_b.msh: a mesh named .geo"
mv "$CASE/case_b.msh" "$CASE/case_b.geo"
sed -i 's/^geometry = .*/geometry = "case_b.geo"/' "$CASE/scene.toml"

total=$n
echo "fuzz_pre: $total cases generated in $WORK; running with $JOBS jobs"

# --- run ----------------------------------------------------------------------------------------
start=$(date +%s)
ls -d "$WORK"/c[0-9]* | xargs -P "$JOBS" -n 1 bash "$SELF" --check "$LITUYA" >"$WORK/failures.txt"
end=$(date +%s)
accepted=$(cat "$WORK"/c*/code.txt 2>/dev/null | grep -c '^0$')
refused=$(cat "$WORK"/c*/code.txt 2>/dev/null | grep -c '^1$')
failed=$(ls "$WORK"/c*/fail.txt 2>/dev/null | wc -l | tr -d ' ')
echo "fuzz_pre: $total cases in $((end - start)) s: $accepted accepted (exit 0)," \
  "$refused refused (exit 1), $failed failed"
if [ "$failed" -ne 0 ] || [ "$total" -lt 300 ]; then
  cat "$WORK"/c*/fail.txt 2>/dev/null
  [ "$total" -lt 300 ] && echo "fuzz_pre: only $total cases (at least 300 expected)"
  exit 1
fi
exit 0
