#!/usr/bin/env bash
# Debug rebuild times of a user crate that declares an algebra (issue 26 item 5): a crate with
# gam-ga as a path dependency and the `algebra!` invocation in src/main.rs, rebuilt after a
# one-word edit of main.rs, alternated with the same crate on another tree (an older commit)
# so both see the same machine load. Prints each run and the medians.
#
#   tests/bench/rebuild-times.sh                 # this tree only
#   tests/bench/rebuild-times.sh OLD_TREE        # alternated with a checkout of another commit
#   RUNS=12 ALGEBRA=cga tests/bench/rebuild-times.sh OLD_TREE
#
# ALGEBRA is pga (3D PGA: Plane, Line, Point, Motor; the automatic Odd and Multivector) or cga
# (the full 5-generator CGA: Vector, Bivector, Motor, Multivector). Crates and their target
# directories go to a temporary directory, removed at the end.
set -euo pipefail

here=$(cd "$(dirname "$0")/../.." && pwd)
old=${1:-}
runs=${RUNS:-8}
algebra=${ALGEBRA:-pga}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

case "$algebra" in
pga) decl='metric builtin "pga3";
        types {
            Plane = grade 1;
            Line = grade 2;
            Point = grade 3;
            Motor = even;
        }'
     use='let p = alg::Plane::<f64>::e1();
    println!("edit 0: {:?}", (p * p).scalar);' ;;
cga) decl='metric builtin "cga";
        types {
            Vector = grade 1;
            Bivector = grade 2;
            Motor = even;
            Multivector = all;
        }'
     use='let v = alg::Vector::<f64>::e1();
    println!("edit 0: {}", (v * v).scalar);' ;;
*) echo "error: ALGEBRA is pga or cga" >&2; exit 2 ;;
esac

# make NAME TREE: a crate depending on TREE's gam-ga
make() {
    mkdir -p "$work/$1/src"
    cat > "$work/$1/Cargo.toml" <<EOF
[package]
name = "$1"
version = "0.1.0"
edition = "2024"

[dependencies]
gam-ga = { path = "$2/gam-ga" }
EOF
    cat > "$work/$1/src/main.rs" <<EOF
gam_ga::algebra! {
    /// The declaration under test.
    pub mod alg {
        $decl
    }
}

fn main() {
    $use
}
EOF
    (cd "$work/$1" && cargo build -q)
}

crates=(new)
make new "$here"
if [ -n "$old" ]; then
    make old "$(cd "$old" && pwd)"
    crates=(old new)
fi

for r in $(seq "$runs"); do
    for c in "${crates[@]}"; do
        cd "$work/$c"
        sed -i "s/edit [0-9]*:/edit $r$RANDOM:/" src/main.rs
        s=$(date +%s.%N)
        cargo build -q
        e=$(date +%s.%N)
        echo "$c $(echo "$e - $s" | bc)"
    done
done | tee "$work/times"
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
for c in "${crates[@]}"; do
    printf '%s median %s s\n' "$c" "$(grep "^$c " "$work/times" | cut -d' ' -f2 | sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}')"
done
