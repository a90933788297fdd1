#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Mutation testing: plants each one-line bug of tests/mutation/mutations.txt in a copy of the sources, builds the
# core tests (satviz_tests) and runs them; a mutation is caught when a test fails (or hangs), missed when they all
# pass. The checkout is never modified: the copy lives in a work directory (default build/mutation), kept between
# runs so that each mutation rebuilds only what its file touches; each run first makes the copy equal to the
# checkout again (an interrupted run may have left a mutation in it). The tests' output for each mutation is kept
# there as test-ID.log.
#
#   tests/mutation/run.sh                 every mutation
#   tests/mutation/run.sh ID...           only these
#   tests/mutation/run.sh --list          the mutations and what each breaks
#   tests/mutation/run.sh --check         only check that every mutation applies (its fragment occurs once)
#
# Environment: SATVIZ_MUTATION_DIR (work directory), SATVIZ_MUTATION_JOBS (build jobs, default 1),
# SATVIZ_MUTATION_TIMEOUT (seconds per test run; default four times the unmutated run, at least 300).
# Exit status: 0 when every mutation run was caught, 1 when one was missed or did not compile, 2 on a setup error.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
list="$here/mutations.txt"
work="${SATVIZ_MUTATION_DIR:-$root/build/mutation}"
jobs="${SATVIZ_MUTATION_JOBS:-1}"

die() {
    echo "run.sh: $*" >&2
    exit 2
}

# The mutations of the list (see its header): id, file, original fragment and replacement of each, and what it
# breaks.
declare -a ids=() files=() froms=() tos=()
declare -A descriptions=()
parse() {
    local id="" file="" from="" to="" what="" line key value
    local have_from=0 have_to=0
    flush() {
        if [[ -n "$id" ]]; then
            [[ -n "$file" && $have_from == 1 && $have_to == 1 ]] || die "$list: [$id] needs file, from and to"
            [[ -z "${descriptions[$id]+x}" ]] || die "$list: [$id] appears twice"
            ids+=("$id")
            files+=("$file")
            froms+=("$from")
            tos+=("$to")
            descriptions[$id]="$what"
        fi
        id="" file="" from="" to="" what="" have_from=0 have_to=0
    }
    while IFS= read -r line || [[ -n "$line" ]]; do
        [[ "$line" =~ ^[[:space:]]*(#|$) ]] && continue
        if [[ "$line" =~ ^\[([A-Za-z0-9_.-]+)\]$ ]]; then
            flush
            id="${BASH_REMATCH[1]}"
            continue
        fi
        [[ -n "$id" ]] || die "$list: '$line' before the first [id]"
        [[ "$line" =~ ^([a-z]+):\ (.*)$ ]] || die "$list: [$id]: cannot read '$line'"
        key="${BASH_REMATCH[1]}"
        value="${BASH_REMATCH[2]}"
        case "$key" in
        what) what="$value" ;;
        file) file="$value" ;;
        from) from="$value" have_from=1 ;;
        to) to="$value" have_to=1 ;;
        *) die "$list: [$id]: unknown key '$key'" ;;
        esac
    done <"$list"
    flush
}

# How often `fragment` occurs in `file` (every occurrence, several on a line included).
occurrences() {
    FRAGMENT="$2" awk '
        { line = $0; while ((k = index(line, ENVIRON["FRAGMENT"])) > 0) { n++; line = substr(line, k + 1) } }
        END { print n + 0 }' "$1"
}

# Writes `file` with its one occurrence of `from` replaced by `to` (exact strings, no patterns).
mutate() {
    local file="$1" from="$2" to="$3" tmp
    tmp="$(mktemp)"
    FROM="$from" TO="$to" awk '
        { k = index($0, ENVIRON["FROM"]) }
        k > 0 { $0 = substr($0, 1, k - 1) ENVIRON["TO"] substr($0, k + length(ENVIRON["FROM"])) }
        { print }' "$file" >"$tmp"
    cat "$tmp" >"$file"
    rm -f "$tmp"
}

# Every fragment occurs exactly once in the checkout's file, and the replacement differs from it.
check() {
    local k bad=0
    for k in "${!ids[@]}"; do
        local source="$root/${files[$k]}"
        if [[ ! -f "$source" ]]; then
            echo "[${ids[$k]}] ${files[$k]}: no such file" >&2
            bad=1
        elif [[ "${froms[$k]}" == "${tos[$k]}" ]]; then
            echo "[${ids[$k]}] the replacement is the fragment itself" >&2
            bad=1
        else
            local n
            n="$(occurrences "$source" "${froms[$k]}")"
            if [[ "$n" != 1 ]]; then
                echo "[${ids[$k]}] ${files[$k]}: the fragment occurs $n times, not once: ${froms[$k]}" >&2
                bad=1
            fi
        fi
    done
    return $bad
}

# The sources the core tests need, copied into the work tree where they differ (so that make rebuilds only those).
sync_sources() {
    local path
    mkdir -p "$work/src"
    (cd "$root" && find CMakeLists.txt cmake core tests tutorials/CMakeLists.txt tutorials/figures.cmake -type f \
        -not -path 'tests/fuzz/corpus/*' -not -path 'tests/data/*' -print) |
        while IFS= read -r path; do
            if ! cmp -s "$root/$path" "$work/src/$path"; then
                mkdir -p "$(dirname "$work/src/$path")"
                cp "$root/$path" "$work/src/$path"
            fi
        done
}

build() {
    cmake --build "$work/build" --target satviz_tests -j "$jobs" >"$work/build.log" 2>&1
}

# Runs the tests, stopping at the first failure; sets `caught_by` to the first failing test case and `verdict`.
run_tests() {
    local seconds="$1" status=0
    timeout "$seconds" "$work/build/tests/satviz_tests" --abort >"$work/test.log" 2>&1 || status=$?
    caught_by=""
    if [[ $status == 0 ]]; then
        verdict="missed"
    elif [[ $status == 124 ]]; then
        verdict="caught"
        caught_by="(no answer within ${seconds} s)"
    else
        verdict="caught"
        # Catch2's console reporter names a test case between two rules of dashes, wrapped over lines when it is
        # long, before each of its failures and each of its warnings: the failing one is the last named before the
        # first "FAILED:".
        caught_by="$(awk '/^--------------------+$/ { if (open) { open = 0; name = text } else { open = 1; text = ""; sep = "" } next }
            open { text = text sep $0; sep = " "; next }
            /FAILED:$/ { print name; exit }' "$work/test.log")"
        [[ -n "$caught_by" ]] || caught_by="(exit status $status)"
    fi
}

parse
case "${1:-}" in
--list)
    for k in "${!ids[@]}"; do
        printf '%-30s %s\n' "${ids[$k]}" "${files[$k]}"
        printf '%-30s %s\n' "" "${descriptions[${ids[$k]}]}"
    done
    exit 0
    ;;
--check)
    check || exit 1
    echo "${#ids[@]} mutations, each applies once"
    exit 0
    ;;
-*)
    die "unknown option $1 (see the top of $0)"
    ;;
esac
check || die "fix $list first"

# The mutations to run: all, or those named.
selected=()
if [[ $# -gt 0 ]]; then
    for wanted in "$@"; do
        found=""
        for k in "${!ids[@]}"; do
            [[ "${ids[$k]}" == "$wanted" ]] && found="$k"
        done
        [[ -n "$found" ]] || die "no mutation named $wanted (see --list)"
        selected+=("$found")
    done
else
    selected=("${!ids[@]}")
fi

echo "work directory: $work"
sync_sources
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DSATVIZ_BUILD_TESTS=ON -DSATVIZ_BUILD_TOOLS=OFF \
    -DSATVIZ_BUILD_RENDER=OFF -DSATVIZ_BUILD_APP=OFF -DSATVIZ_BUILD_BENCH=OFF -DSATVIZ_BUILD_FUZZ=OFF \
    >"$work/configure.log" 2>&1 || die "configuring failed, see $work/configure.log"

# The unmutated sources must build and pass, or no verdict means anything. A test binary identical to one that
# passed before is not run again.
start=$SECONDS
build || die "the unmutated sources do not build, see $work/build.log"
echo "unmutated: built in $((SECONDS - start)) s"
binary="$work/build/tests/satviz_tests"
if cmp -s "$binary" "$work/passed/satviz_tests" && [[ -f "$work/passed/seconds" ]]; then
    baseline="$(cat "$work/passed/seconds")"
    echo "unmutated: the same test binary passed before, in ${baseline} s"
else
    start=$SECONDS
    "$binary" >"$work/test.log" 2>&1 || die "the unmutated tests fail, see $work/test.log"
    baseline=$((SECONDS - start))
    mkdir -p "$work/passed"
    cp "$binary" "$work/passed/satviz_tests"
    echo "$baseline" >"$work/passed/seconds"
    echo "unmutated: tests pass in ${baseline} s"
fi
limit="${SATVIZ_MUTATION_TIMEOUT:-$((baseline * 4 > 300 ? baseline * 4 : 300))}"
echo "a mutated run gets ${limit} s"
echo

caught=0
missed=0
broken=0
for k in "${selected[@]}"; do
    id="${ids[$k]}"
    file="${files[$k]}"
    copy="$work/src/$file"
    start=$SECONDS
    mutate "$copy" "${froms[$k]}" "${tos[$k]}"
    if cmp -s "$copy" "$root/$file"; then
        cp "$root/$file" "$copy"
        die "[$id] the mutation changed nothing"
    fi
    if build; then
        run_tests "$limit"
        cp "$work/test.log" "$work/test-$id.log"
    else
        cp "$work/build.log" "$work/build-$id.log"
        verdict="did not compile"
        caught_by="see $work/build-$id.log"
    fi
    # Restored with a new time stamp, so that the next build recompiles what the mutation touched.
    cp "$root/$file" "$copy"
    case "$verdict" in
    caught) caught=$((caught + 1)) ;;
    missed) missed=$((missed + 1)) ;;
    *) broken=$((broken + 1)) ;;
    esac
    printf '%-30s %-15s %5d s  %s\n' "$id" "$verdict" "$((SECONDS - start))" "$caught_by"
done

# Leave the work tree as the checkout is, built, so that the next run starts from there.
build || true
echo
echo "mutation score: $caught of ${#selected[@]} caught ($missed missed, $broken did not compile)"
[[ $missed == 0 && $broken == 0 ]]
