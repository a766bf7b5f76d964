#!/bin/sh
# A class set as one process: 1000 claims (the corpus's general-body claims, true and false,
# repeated in order) in one file, checked by `kinetics check --claims` in parallel. Prints
# the summary line and the wall time; build first with `cargo build --release`.
#
#     sh benches/check_class_set.sh
set -e
cd "$(dirname "$0")/.."
claims=target/class_set.claims
grep '^general |' tests/data/check_corpus.txt | cut -d'|' -f4- | sed 's/^ //' > target/class_set.one
: > "$claims"
while [ "$(wc -l < "$claims")" -lt 1000 ]; do cat target/class_set.one >> "$claims"; done
head -n 1000 "$claims" > target/class_set.tmp && mv target/class_set.tmp "$claims"
start=$(date +%s.%N)
target/release/kinetics check --claims "$claims" | tail -n 1 || true
end=$(date +%s.%N)
echo "1000 claims in one process: $(echo "$end - $start" | bc) s"
