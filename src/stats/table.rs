//! Rows of Markdown tables.

/// One row of a Markdown table, `cells` between bars, with its newline.
pub fn table_row(cells: &[String]) -> String {
    format!("| {} |\n", cells.join(" | "))
}

#[cfg(test)]
mod tests {
    #[test]
    fn cells_between_bars() {
        assert_eq!(super::table_row(&["a".into(), "1".into()]), "| a | 1 |\n");
    }
}
