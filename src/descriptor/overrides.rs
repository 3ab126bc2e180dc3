//! Key-path overrides of a descriptor table: how sweep values, `[quick]`
//! and `--replicas` are applied (`scene.species.0.count` = 7).

/// Set the dotted key `path` of `doc` to `value`, creating tables on the way.
/// A numeric segment indexes an array (`scene.species.0.count`); below
/// `sweep.parameters.` the rest of the path is one key (a swept key path).
pub fn apply_overrides(
    doc: &mut toml::Table,
    path: &str,
    value: toml::Value,
) -> Result<(), String> {
    // Sweep parameters are themselves named by key paths: the rest is one key.
    let segments: Vec<&str> = match path.strip_prefix("sweep.parameters.") {
        Some(key) => vec!["sweep", "parameters", key],
        None => path.split('.').collect(),
    };
    if segments.iter().any(|s| s.trim().is_empty()) {
        return Err(format!(
            "`{path}` is not a key path; write keys separated by dots, e.g. `scene.piston.mass`"
        ));
    }
    let (last, parents) = segments.split_last().ok_or("empty key path")?;
    let mut slot = Slot::Table(doc);
    let mut walked = String::new();
    for segment in parents {
        slot = slot.child(segment, &walked)?;
        if !walked.is_empty() {
            walked.push('.');
        }
        walked.push_str(segment);
    }
    slot.set(last, &walked, value)
}

/// A container being walked by `apply_overrides`.
enum Slot<'a> {
    Table(&'a mut toml::Table),
    Array(&'a mut Vec<toml::Value>),
}

impl<'a> Slot<'a> {
    fn child(self, segment: &str, walked: &str) -> Result<Slot<'a>, String> {
        let value = match self {
            Slot::Table(t) => t
                .entry(segment.to_string())
                .or_insert_with(|| toml::Value::Table(toml::Table::new())),
            Slot::Array(a) => {
                let len = a.len();
                index(segment, walked, len)
                    .and_then(|i| a.get_mut(i).ok_or_else(|| out_of_range(i, walked, len)))?
            }
        };
        match value {
            toml::Value::Table(t) => Ok(Slot::Table(t)),
            toml::Value::Array(a) => Ok(Slot::Array(a)),
            other => Err(format!(
                "`{}` is a {}, not a table, so it has no key `{segment}`",
                join(walked, segment),
                other.type_str()
            )),
        }
    }

    fn set(self, segment: &str, walked: &str, value: toml::Value) -> Result<(), String> {
        match self {
            Slot::Table(t) => {
                t.insert(segment.to_string(), value);
                Ok(())
            }
            Slot::Array(a) => {
                let len = a.len();
                let i = index(segment, walked, len)?;
                let item = a.get_mut(i).ok_or_else(|| out_of_range(i, walked, len))?;
                *item = value;
                Ok(())
            }
        }
    }
}

fn join(walked: &str, segment: &str) -> String {
    if walked.is_empty() {
        segment.to_string()
    } else {
        format!("{walked}.{segment}")
    }
}

fn index(segment: &str, walked: &str, len: usize) -> Result<usize, String> {
    segment.parse::<usize>().map_err(|_| {
        format!(
            "`{walked}` is a list of {len}; index it by number (`{walked}.0`), not by `{segment}`"
        )
    })
}

fn out_of_range(i: usize, walked: &str, len: usize) -> String {
    format!("`{walked}` has {len} item(s), so index {i} does not exist; use 0..{len}")
}
