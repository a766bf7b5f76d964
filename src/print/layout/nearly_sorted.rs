//! The sort the presented orders go through (rules 2, 3 and 4): the factors of a term, the
//! groups of a sum and the terms of a coefficient are short and often in order already, so
//! they are sorted by insertion, which compares each neighbouring pair once when nothing is
//! out of place.

use crate::algebra::work;
use std::cmp::Ordering;

/// Sorts a short slice that is often in order already (the factors of a term, the groups
/// of a sum) as `sort_by` would, stably: by insertion, comparing each neighbouring pair once
/// when nothing is out of place. Long slices go to the standard sort. The comparisons are
/// counted against the command's work budget.
#[inline]
pub(super) fn sort_nearly_sorted<T: Copy>(
    items: &mut [T],
    mut order: impl FnMut(&T, &T) -> Ordering,
) {
    if items.len() > 16 {
        let n = items.len() as u64;
        work::count(n * u64::from(n.ilog2()));
        items.sort_by(order);
        return;
    }
    work::count(items.len() as u64);
    for i in 1..items.len() {
        if order(&items[i - 1], &items[i]) != Ordering::Greater {
            continue;
        }
        let item = items[i];
        let mut j = i - 1;
        items[i] = items[j];
        while j > 0 && order(&items[j - 1], &item) == Ordering::Greater {
            items[j] = items[j - 1];
            j -= 1;
        }
        items[j] = item;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Short and long slices, in order, reversed and shuffled, with ties: the same order as
    /// the standard stable sort, ties in their given order.
    #[test]
    fn sorts_as_the_stable_sort_does() {
        for len in [0, 1, 2, 5, 16, 17, 40] {
            let patterns: [fn(usize) -> u32; 3] = [
                |i| i as u32 / 2,
                |i| 100 - i as u32 / 3,
                |i| (i as u32 * 7919) % 13,
            ];
            for key in patterns {
                let items: Vec<(u32, usize)> = (0..len).map(|i| (key(i), i)).collect();
                let mut expected = items.clone();
                expected.sort_by_key(|item| item.0);
                let mut sorted = items;
                sort_nearly_sorted(&mut sorted, |a, b| a.0.cmp(&b.0));
                assert_eq!(sorted, expected, "{len} items");
            }
        }
    }
}
