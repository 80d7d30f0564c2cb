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
        lines.push(table_line(row, &widths));
        if i == 0 {
            lines.push(table_rule(&widths));
        }
    }
    lines.join("\n")
}

/// One line of a [`text_table`] with the column widths `widths` (trailing spaces trimmed).
pub(crate) fn table_line(row: &[String], widths: &[usize]) -> String {
    let mut line = String::new();
    for (j, cell) in row.iter().enumerate() {
        let pad = widths[j] - cell.chars().count();
        line.push_str(cell);
        line.push_str(&" ".repeat(pad));
        line.push_str(if j == 0 { " | " } else { "  " });
    }
    line.trim_end().to_string()
}

/// The rule under the header of a [`text_table`] with the column widths `widths`.
pub(crate) fn table_rule(widths: &[usize]) -> String {
    let total: usize = widths.iter().sum::<usize>() + 3 + 2 * widths.len().saturating_sub(2);
    let mut rule = "-".repeat(total);
    if let Some(w0) = widths.first() {
        rule.replace_range(w0 + 1..w0 + 2, "+");
    }
    rule
}

/// A JSON result with a `samples` array that may be too large to hold: `head` (an object) and
/// sample `i` of `n`. The CLI streams it to stdout ([`Streamed::stream`]); a caller that wants
/// the value (the Python binding) takes [`Streamed::into_value`]. Both give the same JSON.
pub struct Streamed<'a> {
    /// The object the `samples` array is appended to.
    pub head: Value,
    /// The number of samples.
    pub n: usize,
    /// Sample `i`, checked.
    pub sample: Box<dyn Fn(usize) -> Result<Value, crate::error::CliError> + 'a>,
}

impl Streamed<'_> {
    /// The whole result as one value.
    pub fn into_value(self) -> Result<Value, crate::error::CliError> {
        let samples = (0..self.n).map(|i| (self.sample)(i)).collect::<Result<Vec<_>, _>>()?;
        let mut head = self.head;
        head["samples"] = Value::Array(samples);
        Ok(head)
    }

    /// Writes the result to stdout, sample by sample in bounded memory, after a first pass
    /// that computes every sample and discards it (so a failure leaves stdout empty, as the
    /// error contract requires). Returns the empty string: the caller's final newline ends
    /// the JSON.
    pub fn stream(self) -> Result<String, crate::error::CliError> {
        use crate::sample::write_error;
        use std::io::Write;
        for i in 0..self.n {
            (self.sample)(i)?;
        }
        let head = self.head.to_string();
        let open = head.strip_suffix('}').unwrap_or(&head);
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        out.write_all(open.as_bytes()).map_err(write_error)?;
        out.write_all(if open == "{" { b"\"samples\":[" } else { b",\"samples\":[" }).map_err(write_error)?;
        for i in 0..self.n {
            if i > 0 {
                out.write_all(b",").map_err(write_error)?;
            }
            serde_json::to_writer(&mut out, &(self.sample)(i)?).map_err(|e| write_error(e.into()))?;
        }
        out.write_all(b"]}").map_err(write_error)?;
        out.flush().map_err(write_error)?;
        Ok(String::new())
    }
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
