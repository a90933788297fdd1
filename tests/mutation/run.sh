#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Mutation testing: plants each one-line bug of tests/mutation/mutations.txt in a copy of the sources, builds the
# test programs its "tests:" lines name, runs them with the Catch2 test spec of each line and lists every test case
# that fails (without "tests:" lines, all of satviz_tests up to the first failure); a mutation is caught when a test fails (or hangs), missed when they all
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
# SATVIZ_MUTATION_TIMEOUT (seconds per test run; default four times the unmutated run of the same tests, at least 60).
# The build uses ccache when it is installed, so that restoring a file after its mutation costs no compilation.
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
declare -a ids=() files=() froms=() tos=() runs=()
declare -A descriptions=()
parse() {
    local id="" file="" from="" to="" what="" tests="" line key value
    local have_from=0 have_to=0
    flush() {
        if [[ -n "$id" ]]; then
            [[ -n "$file" && $have_from == 1 && $have_to == 1 ]] || die "$list: [$id] needs file, from and to"
            [[ -z "${descriptions[$id]+x}" ]] || die "$list: [$id] appears twice"
            ids+=("$id")
            files+=("$file")
            froms+=("$from")
            tos+=("$to")
            runs+=("${tests:-satviz_tests}")
            descriptions[$id]="$what"
        fi
        id="" file="" from="" to="" what="" tests="" have_from=0 have_to=0
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
        tests)
            [[ "$value" =~ ^satviz_[a-z_]+(\ .+)?$ ]] || die "$list: [$id]: tests: a test program, then a test spec"
            tests="${tests:+$tests$'\n'}$value"
            ;;
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

# The sources the tests need, copied into the work tree where they differ (so that make rebuilds only those).
sync_sources() {
    local path
    mkdir -p "$work/src"
    (cd "$root" && find CMakeLists.txt cmake core render tests tutorials/CMakeLists.txt tutorials/figures.cmake tutorials/scenes -type f \
        -not -path 'tests/fuzz/corpus/*' -not -path 'tests/data/*' -print) |
        while IFS= read -r path; do
            if ! cmp -s "$root/$path" "$work/src/$path"; then
                mkdir -p "$(dirname "$work/src/$path")"
                cp "$root/$path" "$work/src/$path"
            fi
        done
}

# Builds the test programs of the given "tests:" lines.
build() {
    local targets
    targets="$(printf '%s\n' "$@" | awk '{ print $1 }' | sort -u | tr '\n' ' ')"
    # shellcheck disable=SC2086
    cmake --build "$work/build" --target $targets -j "$jobs" >"$work/build.log" 2>&1
}

# Runs one "tests:" line (a program and an optional Catch2 test spec, where "[#file]" names a test file) with the
# XML reporter into `log`; prints the name of every test case that failed, one a line. Returns the program's status.
run_line() {
    local line="$1" seconds="$2" log="$3" program spec status=0
    program="${line%% *}"
    spec=""
    [[ "$line" == *" "* ]] && spec="${line#* }"
    local args=(-# -r xml -o "$log")
    # A line without a spec runs the whole program, up to its first failure (it is long).
    if [[ -n "$spec" ]]; then
        args+=("$spec")
    else
        args+=(--abort)
    fi
    timeout "$seconds" "$work/build/tests/$program" "${args[@]}" >/dev/null 2>&1 || status=$?
    # A test case's element carries its name; its result comes last in it (sections report results of their own).
    awk '/<TestCase name="/ { name = $0; sub(/.*<TestCase name="/, "", name); sub(/".*/, "", name); depth = 0 }
        /<OverallResult success="false"/ { print name }' "$log" 2>/dev/null |
        sed -e 's/&quot;/"/g' -e "s/&apos;/'/g" -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&amp;/\&/g' | awk '!seen[$0]++'
    return $status
}

# The key under which the unmutated time of a "tests:" line is kept.
line_key() {
    printf '%s' "$1" | md5sum | cut -c1-16
}

# Runs the "tests:" lines of one mutation; sets `caught_by` to the failing test cases (" | " between them) and
# `verdict`.
run_tests() {
    local line status names k=0
    caught_by=""
    verdict="missed"
    while IFS= read -r line; do
        k=$((k + 1))
        status=0
        names="$(run_line "$line" "${limits[$line]}" "$work/test-$k.xml")" || status=$?
        cp "$work/test-$k.xml" "$work/test-$id-$k.xml" 2>/dev/null || true
        if [[ $status == 124 ]]; then
            names="${names:+$names$'\n'}(${line%% *}: no answer within ${limits[$line]} s)"
        elif [[ $status != 0 && -z "$names" ]]; then
            names="(${line%% *}: exit status $status)"
        fi
        if [[ -n "$names" ]]; then
            verdict="caught"
            caught_by="${caught_by:+$caught_by | }$(printf '%s' "$names" | paste -sd '|' | sed 's/|/ | /g')"
        fi
    done <<<"$1"
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
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR="$work"
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DSATVIZ_BUILD_TESTS=ON -DSATVIZ_BUILD_TOOLS=ON \
    -DSATVIZ_BUILD_RENDER=OFF -DSATVIZ_BUILD_APP=OFF -DSATVIZ_BUILD_BENCH=OFF -DSATVIZ_BUILD_FUZZ=OFF "${launcher[@]}" \
    >"$work/configure.log" 2>&1 || die "configuring failed, see $work/configure.log"

# The "tests:" lines of the selected mutations, each once.
declare -A limits=()
all_lines=()
for k in "${selected[@]}"; do
    while IFS= read -r line; do
        [[ -n "${limits[$line]+x}" ]] && continue
        limits[$line]=0
        all_lines+=("$line")
    done <<<"${runs[$k]}"
done

# The unmutated sources must build and pass, or no verdict means anything. Each line's time is kept with a copy of
# the program it ran, and not measured again while the program is the same.
start=$SECONDS
build "${all_lines[@]}" || die "the unmutated sources do not build, see $work/build.log"
echo "unmutated: built in $((SECONDS - start)) s"
mkdir -p "$work/passed"
for line in "${all_lines[@]}"; do
    program="${line%% *}"
    key="$(line_key "$line")"
    if cmp -s "$work/build/tests/$program" "$work/passed/$key.program" && [[ -f "$work/passed/$key.seconds" ]]; then
        baseline="$(cat "$work/passed/$key.seconds")"
    else
        start=$SECONDS
        failed="$(run_line "$line" 100000 "$work/test-unmutated.xml")" ||
            die "the unmutated tests fail ($line): ${failed:-see $work/test-unmutated.xml}"
        baseline=$((SECONDS - start))
        cp "$work/build/tests/$program" "$work/passed/$key.program"
        echo "$baseline" >"$work/passed/$key.seconds"
    fi
    limits[$line]="${SATVIZ_MUTATION_TIMEOUT:-$((baseline * 4 > 60 ? baseline * 4 : 60))}"
    echo "unmutated: $line passes in ${baseline} s; a mutated run gets ${limits[$line]} s"
done
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
    if build "$(printf '%s' "${runs[$k]}")"; then
        run_tests "${runs[$k]}"
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
build "${all_lines[@]}" || true
echo
echo "mutation score: $caught of ${#selected[@]} caught ($missed missed, $broken did not compile)"
[[ $missed == 0 && $broken == 0 ]]
