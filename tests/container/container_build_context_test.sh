#!/usr/bin/env bash
# container_build_context: docker/Dockerfile's build stage cannot drift from the build, in a
# few seconds and without building an image (scripts/container-test does that, by hand).
#
# 1. What the build stage COPYs (less .dockerignore) is copied into an empty folder and
#    configured with the build stage's own cmake options: a folder or file the build needs
#    and the Dockerfile leaves out fails here as it would in `docker build`. Every include
#    folder the compile commands name must be in the copy, and the configured build must have
#    what the image promises: the server, MPI sweeps and the Python module.
# 2. The package lists, against scripts/setup's (the machine every test runs on):
#    - every package the build stage installs is one scripts/setup installs;
#    - every -dev package of scripts/setup that the configured build found (a file CMake
#      read or cached belongs to it or to a -dev package it depends on) is installed by the
#      build stage, so a library the host build uses cannot be missing in the image's build;
#    - the runtime stage installs no -dev package.
#
#   container_build_context_test.sh SOURCE_DIR [CMAKE]
set -euo pipefail
src=$(cd "${1:?usage: container_build_context_test.sh SOURCE_DIR [CMAKE]}" && pwd)
cmake=${2:-cmake}
dockerfile=$src/docker/Dockerfile
tmp=$(mktemp -d "${TMPDIR:-/tmp}/grainlab-build-context.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }

# ---- the Dockerfile, one instruction a line ------------------------------------------------
# Comment lines dropped (also those inside a continued RUN), continuations joined, each line
# prefixed by its stage's name: "build<TAB>COPY engine/ engine/".
awk '
  /^[ \t]*#/ { next }
  { line = line $0 }
  /\\[ \t]*$/ { sub(/\\[ \t]*$/, " ", line); next }
  line ~ /^[ \t]*$/ { line = ""; next }
  {
    gsub(/[ \t]+/, " ", line); sub(/^ /, "", line)
    if (toupper(line) ~ /^FROM /) { n = split(line, w, " "); stage = (n >= 4 && toupper(w[3]) == "AS") ? w[4] : "" }
    print stage "\t" line
    line = ""
  }' "$dockerfile" >"$tmp/instructions"
stage_lines() { awk -F'\t' -v s="$1" '$1 == s { print $2 }' "$tmp/instructions"; }
grep -q "^build	" "$tmp/instructions" || { echo "FAIL: $dockerfile has no stage named build"; exit 1; }

# apt_packages STAGE: the packages its `apt-get install` lines name.
apt_packages() {
  stage_lines "$1" | grep 'apt-get' | sed 's/&&/\n/g' | grep 'apt-get.* install ' |
    sed 's/.* install //' | tr ' ' '\n' | grep -v '^-' | grep -v '^$' | sort -u || true
}
# The cmake options of the build stage's configure step (`cmake -S . -B build ...`).
mapfile -t cmake_options < <(stage_lines build | grep -o 'cmake -S [^&]*' | head -n1 |
  tr ' ' '\n' | grep '^-D' | tr -d "\"'")
((${#cmake_options[@]})) || fail "no 'cmake -S . -B build -D...' step in the build stage"
workdir=$(stage_lines build | awk '$1 == "WORKDIR" { d = $2 } END { print d }')

# ---- 1. the build context, as the build stage sees it --------------------------------------
context=$tmp/context  # what the COPYs read, .dockerignore applied
image_src=$tmp/src    # the build stage's WORKDIR after its COPYs
mkdir -p "$context" "$image_src"
copies=()
while read -r -a words; do
  [[ ${words[0]^^} == COPY ]] || continue
  args=()
  for w in "${words[@]:1}"; do
    [[ $w == --from=* ]] && continue 2  # from another stage, not the context
    [[ $w == --* ]] || args+=("$w")
  done
  ((${#args[@]} >= 2)) || { fail "cannot read: ${words[*]}"; continue; }
  copies+=("${args[*]}")
  for s in "${args[@]:0:${#args[@]}-1}"; do
    s=${s#./}; s=${s%/}
    if [[ -e $src/$s ]]; then
      mkdir -p "$context/$(dirname "$s")"
      cp -a "$src/$s" "$context/$s"
    else
      fail "COPY $s: no such file or folder in the source tree"
    fi
  done
done < <(stage_lines build)
echo "build stage COPYs: $(printf '[%s] ' "${copies[@]}")"

if [[ -f $src/.dockerignore ]]; then
  shopt -s globstar dotglob nullglob
  while IFS= read -r pattern; do
    pattern=${pattern%%#*}; pattern=${pattern//[[:space:]]/}
    [[ -n $pattern ]] || continue
    [[ $pattern != '!'* ]] || { fail ".dockerignore: exceptions (!) are not followed here: $pattern"; continue; }
    pattern=${pattern#/}; pattern=${pattern%/}
    # shellcheck disable=SC2206 # the pattern is a glob on purpose
    matches=("$context"/$pattern)
    ((${#matches[@]})) && rm -rf "${matches[@]}"
  done <"$src/.dockerignore"
  shopt -u globstar dotglob nullglob
fi

for copy in "${copies[@]}"; do
  read -r -a args <<<"$copy"
  dest=${args[-1]}
  [[ $dest == /* ]] || dest=$workdir/$dest
  [[ $dest == "$workdir" || $dest == "$workdir"/* ]] || { fail "COPY to $dest, outside WORKDIR $workdir"; continue; }
  dest=$image_src/${dest#"$workdir"}
  for s in "${args[@]:0:${#args[@]}-1}"; do
    s=${s#./}; s=${s%/}
    [[ -e $context/$s ]] || continue
    if [[ -d $context/$s ]]; then
      mkdir -p "$dest" && cp -a "$context/$s/." "$dest/"
    elif [[ $dest == */ ]]; then
      mkdir -p "$dest" && cp -a "$context/$s" "$dest"
    else
      mkdir -p "$(dirname "$dest")" && cp -a "$context/$s" "$dest"
    fi
  done
done

configure() {  # configure SOURCE BUILD: the build stage's cmake step, compile commands kept
  # Makefiles, as in the image (no CMAKE_GENERATOR there): the package check reads the files
  # CMake read from CMakeFiles/Makefile.cmake.
  "$cmake" -S "$1" -B "$2" -G "Unix Makefiles" "${cmake_options[@]}" \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$2.log" 2>&1
}
build=$tmp/build
echo "configuring the copy: cmake -S . -B build ${cmake_options[*]}"
if configure "$image_src" "$build"; then
  ok "the build stage's copy configures"
  if grep -q 'CMake Warning' "$build.log"; then
    fail "configuring the copy warns (an optional part left out?):"
    grep -A4 'CMake Warning' "$build.log" | sed 's/^/  | /'
  fi
  # Folders the compiler is told to search that the COPYs left out: configure does not
  # notice them, the compile in the image would.
  missing=$(grep -o -- '-I[^ "]*\|-isystem [^ "]*' "$build/compile_commands.json" |
              sed 's/^-I//; s/^-isystem //' | sort -u | grep "^$image_src/" |
              while read -r d; do [[ -d $d ]] || echo "${d#"$image_src"/}"; done || true)
  [[ -z $missing ]] || fail "include folders missing from the copy: $missing"
  for promise in 'GRAINLAB_HAS_SERVER=1:the server' 'GRAINLAB_HAS_MPI=1:MPI sweeps' \
                 'python/src/module.cpp:the Python module'; do
    if grep -q -- "${promise%%:*}" "$build/compile_commands.json"; then
      ok "the configured build has ${promise#*:}"
    else
      fail "the configured build lacks ${promise#*:} (${promise%%:*} is not in its compile commands)"
    fi
  done
else
  fail "the build stage's copy does not configure (the image build would stop here):"
  grep -B1 -A6 'CMake Error' "$build.log" | sed "s|$image_src|<build stage $workdir>|g; s/^/  | /" | head -40
  # The package check needs a configured build: the whole source tree, the same options.
  build=$tmp/build-whole-tree
  configure "$src" "$build" || { echo "FAIL: the source tree does not configure either"; cat "$build.log"; exit 1; }
  echo "(the package check below uses the whole source tree configured with the same options)"
fi

# ---- 2. packages ---------------------------------------------------------------------------
# scripts/setup's packages: its packages=(...) and packages+=(...) lists, comments dropped.
sed 's/#.*//' "$src/scripts/setup" | tr '\n' ' ' |
  grep -o 'packages+\?=([^)]*)' | sed 's/^[^(]*(//; s/)$//' | tr ' ' '\n' | grep -v '^$' |
  sort -u >"$tmp/setup"
apt_packages build >"$tmp/build-stage"
apt_packages runtime >"$tmp/runtime-stage"
[[ -s $tmp/setup ]] || fail "no packages=(...) list in scripts/setup"
[[ -s $tmp/build-stage ]] || fail "no apt-get install in the build stage"
[[ -s $tmp/runtime-stage ]] || fail "no apt-get install in the runtime stage"

extra=$(comm -23 "$tmp/build-stage" "$tmp/setup" | tr '\n' ' ')
if [[ -z $extra ]]; then
  ok "every build-stage package is in scripts/setup"
else
  fail "the build stage installs what scripts/setup does not (the host build never tests with it): $extra"
fi

dev_in_runtime=$(grep -- '-dev$' "$tmp/runtime-stage" | tr '\n' ' ' || true)
if [[ -z $dev_in_runtime ]]; then
  ok "the runtime stage installs no -dev package"
else
  fail "the runtime stage installs -dev packages: $dev_in_runtime"
fi

# The packages whose files the configured build used: the files CMake read (its makefile's
# dependencies) and the paths it cached, outside the build. Standard prefixes are left out:
# every -dev package has files there. A path no package owns is looked up again through its
# links (/usr/bin/mpicxx is an alternatives link to libopenmpi-dev's mpicxx.openmpi).
{
  sed -n '/^set(CMAKE_MAKEFILE_DEPENDS/,/^ *)/p' "$build/CMakeFiles/Makefile.cmake" | grep -o '"/[^"]*"' | tr -d '"'
  grep -E '^[A-Za-z0-9_]+:(FILEPATH|PATH|STRING|INTERNAL)=/' "$build/CMakeCache.txt" | sed 's/^[^=]*=//' | tr ';' '\n'
} | grep -v "^$tmp" | grep -v "^$src" | grep -vxE '/usr(/local)?(/include|/lib|/lib/[a-z0-9_]+-linux-gnu[a-z]*|/share|/bin)?' |
  sort -u | while read -r path; do [[ -e $path ]] && echo "$path"; done >"$tmp/paths" || true
owners() {  # owners < PATHS: the packages owning them; the paths nobody owns to fd 3
  local paths
  mapfile -t paths
  ((${#paths[@]})) || return 0
  { dpkg-query -S "${paths[@]}" 2>&1 || true; } | while IFS= read -r line; do
    case $line in
      *"no path found matching pattern "*) echo "${line##* }" >&3 ;;
      *': '/*) echo "${line%%: /*}" | tr ',' '\n' | sed 's/ //g; s/:.*//' ;;
    esac
  done
  return 0
}
{ owners <"$tmp/paths" 3>"$tmp/unowned"; xargs -r -n1 realpath <"$tmp/unowned" | owners 3>/dev/null; } |
  sort -u >"$tmp/used"
[[ -s $tmp/used ]] || fail "found no package the configured build used (dpkg-query -S answered nothing)"

# dev_closure PKG: PKG and the installed -dev packages it depends on, recursively.
dev_closure() {
  local queue=("$1") seen=" " p
  while ((${#queue[@]})); do
    p=${queue[0]}; queue=("${queue[@]:1}")
    if [[ $seen == *" $p "* ]]; then continue; fi
    seen+="$p "
    echo "$p"
    for d in $(dpkg-query -W -f='${Depends}' "$p" 2>/dev/null | tr ',|' '\n' | sed 's/(.*//; s/:.*//; s/ //g'); do
      if [[ $d == *-dev ]]; then queue+=("$d"); fi
    done
  done
}
needed=()
while read -r p; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' ||
    { fail "scripts/setup's $p is not installed here: run ./scripts/setup"; continue; }
  closure=$(dev_closure "$p")  # whole, not piped into grep -q: pipefail would see a SIGPIPE
  if grep -qxFf "$tmp/used" <<<"$closure"; then needed+=("$p"); fi
done < <(grep -- '-dev$' "$tmp/setup")
echo "scripts/setup's -dev packages the configured build uses: ${needed[*]}"
for p in "${needed[@]}"; do
  grep -qxF "$p" "$tmp/build-stage" ||
    fail "$p: the configured build uses it (scripts/setup installs it), the build stage does not install it"
done

if ((failures)); then
  echo "container_build_context: $failures failure(s) in $dockerfile"
  exit 1
fi
echo "container_build_context: docker/Dockerfile's build stage has what the build needs"
