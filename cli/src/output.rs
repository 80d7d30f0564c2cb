//! Output formats: a multivector as a JSON object (basis name -> coefficient string, in the
//! algebra's basis order, zeros omitted) or in human form (`-2 - e0inf`), and aligned text
//! tables.

use crate::scalar::CliScalar;
use algebra_core::Multivector;
use serde_json::{Map, Value};

/// The JSON object of a multivector: `{"e123":"-2","e0123inf":"1"}`; `{}` for zero.
pub fn mv_json<T: CliScalar>(x: &Multivector<T>) -> Value {
    let map: Map<String, Value> = x.terms().map(|(_, name, c)| (name.to_string(), Value::String(c.format()))).collect();
    Value::Object(map)
}

/// The human form, one line: `1/2*e12 + e3`, `(a + b)*e1`, `-2 - e0inf`; `0` for zero.
/// Coefficients are printed as in JSON.
pub fn mv_human<T: CliScalar>(x: &Multivector<T>) -> String {
    x.format_with(CliScalar::format)
}

/// Renders rows of cells as a text table: the first row is the header, the first column the
/// row labels (followed by `|`); every column padded to its widest cell.
pub fn text_table(rows: &[Vec<String>]) -> String {
    let ncols = rows.iter().map(Vec::len).max().unwrap_or(0);
    let width = |j: usize| rows.iter().filter_map(|r| r.get(j)).map(|c| c.chars().count()).max().unwrap_or(0);
    let widths: Vec<usize> = (0..ncols).map(width).collect();
    let mut lines = Vec::with_capacity(rows.len() + 1);
    for (i, row) in rows.iter().enumerate() {
        let mut line = String::new();
        for (j, cell) in row.iter().enumerate() {
            let pad = widths[j] - cell.chars().count();
            line.push_str(cell);
            line.push_str(&" ".repeat(pad));
            line.push_str(if j == 0 { " | " } else { "  " });
        }
        lines.push(line.trim_end().to_string());
        if i == 0 {
            let total: usize = widths.iter().sum::<usize>() + 3 + 2 * ncols.saturating_sub(2);
            let mut rule = "-".repeat(total);
            if let Some(w0) = widths.first() {
                rule.replace_range(w0 + 1..w0 + 2, "+");
            }
            lines.push(rule);
        }
    }
    lines.join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table() {
        let rows = vec![
            vec![String::new(), "1".into(), "e1".into()],
            vec!["1".into(), "1".into(), "e1".into()],
            vec!["e1".into(), "e1".into(), "1".into()],
        ];
        assert_eq!(text_table(&rows), "   | 1   e1\n---+-------\n1  | 1   e1\ne1 | e1  1");
    }
}
