//! Runs or points grouped by the sweep point they share.

/// Items grouped with the first item of a group they are `same` as, groups
/// in the order of their first items and items in their own order: an
/// order the plan gives, which keys such as floats need not have.
pub fn first_seen<T>(
    items: impl IntoIterator<Item = T>,
    same: impl Fn(&T, &T) -> bool,
) -> Vec<Vec<T>> {
    let mut groups: Vec<Vec<T>> = Vec::new();
    for item in items {
        match groups.iter_mut().find(|g| same(&g[0], &item)) {
            Some(g) => g.push(item),
            None => groups.push(vec![item]),
        }
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_keep_the_order_items_came_in() {
        let g = first_seen([3, 1, 4, 1, 5, 9, 2, 6], |a, b| a % 3 == b % 3);
        assert_eq!(g, vec![vec![3, 9, 6], vec![1, 4, 1], vec![5, 2]]);
        // Near floats join the group of the first of them.
        let g = first_seen([0.3, 0.5, 0.3 + 1e-9], |a: &f64, b: &f64| {
            (a - b).abs() < 1e-7
        });
        assert_eq!(g, vec![vec![0.3, 0.3 + 1e-9], vec![0.5]]);
        assert!(first_seen(Vec::<u8>::new(), |a, b| a == b).is_empty());
    }
}
