//! Which generic figures the report draws when a study writes many names:
//! a per-particle family (`x.<index>`, `velocity_x.<index>`, ...) is drawn
//! for an evenly spaced sample of its particles, and at most `PER_KIND`
//! figures of one kind (scalars, series, histograms) in all. A figure is a
//! file and a picture inlined into `index.html`: 20 000 rods would make
//! 20 000 files and a page of tens of megabytes. The tables keep every name;
//! the report says what it left out.

use super::markdown::code;
use super::plots::evenly;
use crate::observe::catalogue;
use std::collections::BTreeMap;

/// Particles of one per-particle family that get a figure.
pub const PER_FAMILY: usize = 16;
/// Figures of one kind at most.
pub const PER_KIND: usize = 200;

/// The names to draw, in the order given (sorted by name), and a line of
/// Markdown for each cut the report should mention; `table` names the file
/// that holds them all.
pub fn chosen<'a>(names: &[&'a str], what: &str, table: &str) -> (Vec<&'a str>, Vec<String>) {
    let mut families: BTreeMap<String, Vec<(u64, &'a str)>> = BTreeMap::new();
    for &name in names {
        if let Some((family, index)) = family_of(name) {
            families.entry(family).or_default().push((index, name));
        }
    }
    let mut notes = Vec::new();
    let mut keep: std::collections::HashSet<&str> = std::collections::HashSet::new();
    for (family, mut members) in families {
        members.sort_unstable();
        let picked = evenly(&members, PER_FAMILY);
        if picked.len() < members.len() {
            let indices: Vec<String> = picked.iter().map(|(i, _)| i.to_string()).collect();
            notes.push(format!(
                "{}: figures of {} of its {} particles (evenly spaced indices {}); every \
                 particle is in `{table}`.",
                code(&family),
                picked.len(),
                members.len(),
                indices.join(", ")
            ));
        }
        keep.extend(picked.iter().map(|(_, n)| *n));
    }
    let sampled: Vec<&'a str> = names
        .iter()
        .copied()
        .filter(|n| family_of(n).is_none() || keep.contains(n))
        .collect();
    if sampled.len() > PER_KIND {
        notes.push(format!(
            "{what}: figures of the first {PER_KIND} of {} names (by name); all are in `{table}`.",
            sampled.len()
        ));
    }
    (sampled.into_iter().take(PER_KIND).collect(), notes)
}

/// A name one observable writes per particle: its family (the pattern with
/// the other parts filled in, e.g. `velocity_x_early.<index>`) and the
/// particle's index.
fn family_of(name: &str) -> Option<(String, u64)> {
    catalogue::CATALOGUE.iter().find_map(|e| {
        let parts = catalogue::matches(e.writes, name)?;
        let (_, index) = parts.iter().find(|(hole, _)| *hole == "index")?;
        let index: u64 = index.parse().ok()?;
        let mut family = e.writes.to_string();
        for (hole, value) in parts.iter().filter(|(hole, _)| *hole != "index") {
            family = family.replace(&format!("<{hole}>"), value);
        }
        Some((family, index))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn families_are_sampled_evenly_and_kinds_capped() {
        let names: Vec<String> = (0..1000)
            .map(|i| format!("velocity_x.{i}"))
            .chain((0..10).map(|i| format!("velocity_x_early.{i}")))
            .chain(["kinetic_energy".to_string()])
            .collect();
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let (shown, notes) = chosen(&refs, "histograms", "histograms.parquet");
        let each = |prefix: &str| {
            shown
                .iter()
                .filter(|n| n.rsplit_once('.').is_some_and(|(p, _)| p == prefix))
                .count()
        };
        assert_eq!(each("velocity_x"), PER_FAMILY);
        assert_eq!(each("velocity_x_early"), 10);
        assert!(shown.contains(&"velocity_x.0") && shown.contains(&"velocity_x.999"));
        assert!(shown.contains(&"kinetic_energy"));
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(notes[0].contains("16 of its 1000 particles"), "{notes:?}");

        let many: Vec<String> = (0..500).map(|i| format!("result_{i:03}")).collect();
        let refs: Vec<&str> = many.iter().map(String::as_str).collect();
        let (shown, notes) = chosen(&refs, "scalar results", "summary.parquet");
        assert_eq!(shown, refs[..PER_KIND]);
        assert!(notes[0].contains("first 200 of 500"), "{notes:?}");
    }
}
