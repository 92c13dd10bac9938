#!/usr/bin/env bash
# tools/photos.sh: copies the chosen photographs out of the pinned scikit-image wheel, byte for byte, into a new or
# existing directory; never replaces a file (one that exists is refused, exit 2, before anything is written); an
# unknown name is refused the same way. Exit 77 (skipped) where tools/python_env.sh cannot make the venv here.
#
# usage: photos_tool.sh REPO_ROOT
set -euo pipefail
root=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "photos_tool: $*" >&2; exit 1; }

status=0
"$root/tools/python_env.sh" >/dev/null || status=$?
if [[ $status -eq 3 ]]; then
    echo "photos_tool: SKIPPED: tools/python_env.sh cannot make tools/.venv here"
    exit 77
fi
[[ $status -eq 0 ]] || fail "tools/python_env.sh failed (exit $status)"

paths=$("$root/tools/photos.sh" "$work/photos" astronaut.png brick.png | tail -1)
[[ $paths == "$work/photos/astronaut.png,$work/photos/brick.png" ]] || fail "printed '$paths'"
# PNG signatures, and the wheel's size for astronaut.png (791 555 bytes in scikit-image 0.25.2).
for f in astronaut.png brick.png; do
    [[ $(head -c 8 "$work/photos/$f" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "$f is not a PNG"
done
[[ $(stat -c %s "$work/photos/astronaut.png") -eq 791555 ]] || fail "astronaut.png is not the pinned wheel's"

# A file that exists is refused: exit 2, one message, the file unchanged, nothing else written.
echo mine >"$work/photos/coffee.png"
rc=0
"$root/tools/photos.sh" "$work/photos" chelsea.png coffee.png 2>"$work/err" >/dev/null || rc=$?
[[ $rc -eq 2 ]] || fail "an existing file: exit $rc, expected 2"
[[ $(cat "$work/photos/coffee.png") == mine ]] || fail "coffee.png was overwritten"
[[ ! -e $work/photos/chelsea.png ]] || fail "chelsea.png was written although the run was refused"
[[ $(wc -l <"$work/err") -eq 1 ]] && grep -q 'coffee.png exists already' "$work/err" || fail "message: $(cat "$work/err")"

# An unknown name, and a path instead of a name: refused, nothing written (not even the directory).
for name in bogus.png ../README.txt; do
    rc=0
    "$root/tools/photos.sh" "$work/new" "$name" 2>"$work/err" >/dev/null || rc=$?
    [[ $rc -eq 2 ]] || fail "'$name': exit $rc, expected 2"
    [[ ! -e $work/new ]] || fail "'$name': $work/new was made"
    grep -q "is not a file of skimage/data/" "$work/err" || fail "'$name': message: $(cat "$work/err")"
done
echo "photos_tool: complete"
