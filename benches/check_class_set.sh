#!/bin/sh
# A class set as one process: 1000 claims in one file, checked by `kinetics check --claims`
# in parallel. Two sets: the corpus's general-body claims (true and false) repeated in
# order, as a class writes the same lines; and 1000 distinct claims, the same ones with
# both sides multiplied by 2, 3, ... (`2 (H_x) = 2 (I_x w_x - ...)`), so that no form is
# shared between claims. Prints each summary line and the wall time; build first with
# `cargo build --release`.
#
#     sh benches/check_class_set.sh
set -e
cd "$(dirname "$0")/.."
grep '^general |' tests/data/check_corpus.txt | cut -d'|' -f4- | sed 's/^ //' > target/class_set.one
repeated=target/class_set.claims
: > "$repeated"
while [ "$(wc -l < "$repeated")" -lt 1000 ]; do cat target/class_set.one >> "$repeated"; done
head -n 1000 "$repeated" > target/class_set.tmp && mv target/class_set.tmp "$repeated"
distinct=target/class_set_distinct.claims
awk -v n="$(wc -l < target/class_set.one)" '{ line[NR] = $0 }
    END { for (k = 0; k < 1000; k++) {
        text = line[k % n + 1]; factor = int(k / n) + 1
        if (factor == 1) { print text; continue }
        split(text, side, "=")
        sub(/^ +/, "", side[1]); sub(/ +$/, "", side[1]); sub(/^ +/, "", side[2])
        print factor " (" side[1] ") = " factor " (" side[2] ")" } }' target/class_set.one > "$distinct"
for set in "$repeated" "$distinct"; do
    start=$(date +%s.%N)
    target/release/kinetics check --claims "$set" | tail -n 1 || true
    end=$(date +%s.%N)
    echo "  $set, one process: $(echo "$end - $start" | bc) s"
done
