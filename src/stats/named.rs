//! Short texts kept one to a line in a Markdown file, each line opening
//! with its name and ": ": captions, and a finding's sentence for each
//! outcome.

/// The text of the line named `name`, empty if there is none.
pub fn named<'a>(text: &'a str, name: &str) -> &'a str {
    (text.lines())
        .find_map(|l| l.strip_prefix(name)?.strip_prefix(": "))
        .unwrap_or("")
}

/// The names of the lines of `text`, in order.
pub fn names(text: &str) -> impl Iterator<Item = &str> {
    text.lines().filter_map(|l| Some(l.split_once(": ")?.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_finds_its_own_line_only() {
        let text = "speed: of {label}\nspeed_std: spread\n";
        assert_eq!(named(text, "speed"), "of {label}");
        assert_eq!(named(text, "speed_std"), "spread");
        assert_eq!(named(text, "sp"), "");
        assert_eq!(names(text).collect::<Vec<_>>(), ["speed", "speed_std"]);
    }
}
