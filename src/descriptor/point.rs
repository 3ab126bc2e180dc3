//! The descriptor of one sweep point or case: the base descriptor with some
//! keys set. Built from a copy of the base table that leaves out what no
//! point needs (`[sweep]`, `[[case]]`, `[quick]`: applied already) and what
//! may be long but no setting touches (explicit positions and velocities):
//! those lists are shared with the base's typed descriptor. So a point
//! costs the size of the descriptor's short part, and a plan is linear in
//! its points whatever the lists hold.

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::from_owned_table;
use crate::descriptor::overrides::apply_overrides;
use crate::model::descriptor::Descriptor;
use crate::model::scene::{Placement, Velocities};

/// Lists that may hold a number per particle, by key path.
const LONG: [[&str; 3]; 2] = [
    ["scene", "placement", "positions"],
    ["scene", "velocities", "velocities"],
];

/// The base of a plan's points.
pub struct PointBase<'a> {
    file: &'a str,
    base: &'a Descriptor,
    /// The table `base` was typed from.
    table: &'a toml::Table,
    /// `table` without `[sweep]`, `[[case]]`, `[quick]`, and with each long
    /// list present replaced by an empty one.
    short: toml::Table,
    /// Which of `LONG` were replaced.
    long: Vec<usize>,
}

/// Why a point's descriptor could not be made.
#[derive(Debug)]
pub enum PointError {
    /// Setting number `.0` does not apply (a path through a value that is
    /// not a table, an index out of range): what is wrong.
    Apply(usize, String),
    /// The settings applied, the table is not a descriptor (serde's words).
    Typed(DescriptorError),
}

impl<'a> PointBase<'a> {
    /// `table` must be the table `base` was typed from.
    pub fn new(file: &'a str, table: &'a toml::Table, base: &'a Descriptor) -> Self {
        let long: Vec<usize> = (0..LONG.len())
            .filter(|&i| list_in(table, &LONG[i]).is_some())
            .collect();
        let short = copy_short(table, &long);
        PointBase {
            file,
            base,
            table,
            short,
            long,
        }
    }

    /// The descriptor with `settings` (key path, value) applied in order.
    pub fn descriptor(&self, settings: &[(String, toml::Value)]) -> Result<Descriptor, PointError> {
        let mut table = self.short.clone();
        // A setting at, inside or above a long list needs the list itself.
        let touched = |path: &[&str; 3]| {
            settings.iter().any(|(key, _)| {
                let keys: Vec<&str> = key.split('.').collect();
                let n = keys.len().min(path.len());
                keys[..n] == path[..n]
            })
        };
        let mut shared = Vec::new();
        for &i in &self.long {
            if !touched(&LONG[i]) {
                shared.push(i);
            } else if let (Some(slot), Some(list)) =
                (list_at(&mut table, &LONG[i]), list_in(self.table, &LONG[i]))
            {
                *slot = list.clone();
            }
        }
        for (n, (key, value)) in settings.iter().enumerate() {
            apply_overrides(&mut table, key, value.clone()).map_err(|m| PointError::Apply(n, m))?;
        }
        let mut d = from_owned_table(self.file, table).map_err(PointError::Typed)?;
        for i in shared {
            self.share(i, &mut d);
        }
        Ok(d)
    }

    /// Put the base's long list `LONG[i]` back where its empty stand-in is.
    fn share(&self, i: usize, d: &mut Descriptor) {
        match i {
            0 => {
                if let (
                    Some(Placement::Explicit { positions }),
                    Some(Placement::Explicit { positions: base }),
                ) = (&mut d.scene.placement, &self.base.scene.placement)
                    && positions.is_empty()
                {
                    *positions = base.clone();
                }
            }
            _ => {
                if let (
                    Some(Velocities::Explicit { velocities }),
                    Some(Velocities::Explicit { velocities: base }),
                ) = (&mut d.scene.velocities, &self.base.scene.velocities)
                    && velocities.is_empty()
                {
                    *velocities = base.clone();
                }
            }
        }
    }
}

/// The array at `path` in `table`, if there is one.
fn list_at<'t>(table: &'t mut toml::Table, path: &[&str; 3]) -> Option<&'t mut toml::Value> {
    let value = table
        .get_mut(path[0])?
        .as_table_mut()?
        .get_mut(path[1])?
        .as_table_mut()?
        .get_mut(path[2])?;
    value.is_array().then_some(value)
}

fn list_in<'t>(table: &'t toml::Table, path: &[&str; 3]) -> Option<&'t toml::Value> {
    let value = table.get(path[0])?.get(path[1])?.get(path[2])?;
    value.is_array().then_some(value)
}

/// A copy of `table` without `[sweep]`, `[[case]]` and `[quick]`, with the
/// lists `LONG[i]` (i in `long`) left empty; they are never copied.
fn copy_short(table: &toml::Table, long: &[usize]) -> toml::Table {
    let mut short = toml::Table::new();
    for (key, value) in table {
        if matches!(key.as_str(), "sweep" | "case" | "quick") {
            continue;
        }
        let below: Vec<&[&str; 3]> = long
            .iter()
            .map(|&i| &LONG[i])
            .filter(|p| p[0] == key)
            .collect();
        let copy = match value {
            toml::Value::Table(t) if !below.is_empty() => {
                toml::Value::Table(copy_without(t, &below))
            }
            _ => value.clone(),
        };
        short.insert(key.clone(), copy);
    }
    short
}

/// `table` (a top-level table) copied with the lists at `paths` (below it)
/// empty.
fn copy_without(table: &toml::Table, paths: &[&[&str; 3]]) -> toml::Table {
    let mut out = toml::Table::new();
    for (key, value) in table {
        let lists: Vec<&str> = paths.iter().filter(|p| p[1] == key).map(|p| p[2]).collect();
        let copy = match value {
            toml::Value::Table(inner) if !lists.is_empty() => {
                let mut t = toml::Table::new();
                for (k, v) in inner {
                    let empty = lists.contains(&k.as_str()) && v.is_array();
                    t.insert(
                        k.clone(),
                        if empty {
                            toml::Value::Array(Vec::new())
                        } else {
                            v.clone()
                        },
                    );
                }
                toml::Value::Table(t)
            }
            _ => value.clone(),
        };
        out.insert(key.clone(), copy);
    }
    out
}
