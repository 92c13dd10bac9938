#!/usr/bin/env bash
# Copies photographs out of scikit-image's wheel (pinned in tools/requirements-nodeps.txt, installed into
# tools/.venv by tools/python_env.sh: no network once the venv exists) for bench --footprints --textures.
#
# usage: tools/photos.sh OUT_DIR [NAME...]
#   NAME: files of skimage/data/ (default: astronaut.png coffee.png chelsea.png brick.png). OUT_DIR is made if
#   missing (its parent must exist). Each file is created exclusively: one that exists already is refused, and
#   nothing is written then; on a failure part-way the files this run created are removed. Prints the paths,
#   comma-separated, on the last stdout line (for --textures).
# Exit status: 2 bad arguments or an existing file, 3 the venv cannot be made here (tools/python_env.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

if [[ $# -lt 1 || $1 == -* ]]; then
    echo "usage: $0 OUT_DIR [NAME...]   (NAME: a file of scikit-image's skimage/data/)" >&2
    exit 2
fi
out=$1
shift
names=("$@")
[[ ${#names[@]} -gt 0 ]] || names=(astronaut.png coffee.png chelsea.png brick.png)

status=0
py=$("$root/tools/python_env.sh" | tail -1) || status=$?
if [[ $status -ne 0 ]]; then
    echo "photos: tools/python_env.sh failed (exit $status): no venv with scikit-image" >&2
    exit "$status"
fi
# The package's folder without importing it (its Python code needs dependencies it was installed without).
data=$("$py" -c 'import importlib.util, os; print(os.path.join(importlib.util.find_spec("skimage").submodule_search_locations[0], "data"))')

# Every check before anything is written.
[[ -d $(dirname -- "$out") ]] || { echo "photos: $out: the parent directory does not exist" >&2; exit 2; }
[[ ! -e $out || -d $out ]] || { echo "photos: $out: exists and is not a directory" >&2; exit 2; }
for name in "${names[@]}"; do
    if [[ $name == */* || ! -f $data/$name ]]; then
        echo "photos: '$name' is not a file of skimage/data/ (there: $(cd "$data" && ls ./*.png ./*.jpg | sed 's|^\./||' | tr '\n' ' '))" >&2
        exit 2
    fi
    [[ ! -e $out/$name ]] || { echo "photos: $out/$name exists already (not overwritten)" >&2; exit 2; }
done

created=()
made_dir=0
cleanup() {
    for f in "${created[@]}"; do rm -f -- "$f"; done
    if [[ $made_dir == 1 ]]; then rmdir -- "$out" 2>/dev/null || true; fi
}
trap 'cleanup; exit 1' ERR INT TERM
if [[ ! -d $out ]]; then
    mkdir -- "$out"
    made_dir=1
fi
set -o noclobber # '>' creates exclusively (O_EXCL): a file that appeared meanwhile is not overwritten
paths=()
for name in "${names[@]}"; do
    cat -- "$data/$name" >"$out/$name"
    created+=("$out/$name")
    paths+=("$out/$name")
done
trap - ERR INT TERM
(IFS=,; echo "${paths[*]}")
