//! The expression language of `gam eval`: a tokenizer and a recursive-descent parser that
//! build an [`Node`] tree whose nodes carry 1-based columns for error messages.
//!
//! Grammar, highest precedence first (cli.md):
//!
//! ```text
//! atom    := NUMBER | IDENT | IDENT '(' [sum (',' sum)*] ')' | '(' sum ')'
//! power   := atom ['**' INTEGER]                -- a power by a non-negative integer literal
//! prefix  := ('-' | '~') prefix | power         -- negation, reverse
//! wedge   := prefix ('^' prefix)*               -- outer product, left-associative
//! product := wedge (('*' | '/') wedge)*         -- geometric product, division
//! sum     := product (('+' | '-') product)*
//! ```
//!
//! NUMBER is `digits`, `digits.digits` or `.digits`, optionally followed by an exponent: `e`
//! with a sign and digits, or `E` with an optional sign and digits (`6e-17`, `1e+3`, `2.5E3`).
//! A lowercase `e` directly followed by digits (`2e1`) is refused: as ambiguous when the
//! algebra has the basis element (`e1`: write `2*e1` or `2e+1`), else with the exponent's
//! spellings (`2e5` in g3: write `2e+5` or `2E5`). IDENT is a letter followed by letters, digits or `_`. Chains of a
//! left-associative operator are kept flat ([`Node::Chain`]) so that long sums do not make
//! deep trees; nesting (parentheses, prefixes, calls) is limited to [`MAX_DEPTH`].
//!
//! `**` binds tighter than the prefix operators, as in Python and in what `gam eval --scalar
//! poly` prints: `-x**2` is `-(x**2)`, so a printed polynomial reads back as itself. The
//! exponent is a literal `0 ..= MAX_EXPONENT`; a chain `x**2**3` is refused (write the
//! parentheses), and `^` stays the outer product.

use crate::error::CliError;
use algebra_core::Algebra;

/// The deepest nesting of parentheses, prefix operators and calls accepted.
pub const MAX_DEPTH: usize = 200;

/// The largest exponent literal of `x ** k` (the size of the result is checked against the
/// work budget when it is evaluated).
pub const MAX_EXPONENT: u32 = 1_000_000_000;

/// The functions of the expression language, with their arities.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    /// `rev(x)`: the reverse.
    Rev,
    /// `inv(x)`: the inverse.
    Inv,
    /// `grade(x, k)`: the true grade-k part.
    Grade,
    /// `bgrade(x, k)`: the part with k generators in the chosen basis.
    BasisGrade,
    /// `brev(x)`: the reverse by subset size in the chosen basis.
    BasisRev,
    /// `lc(x, y)`: left contraction.
    Lc,
    /// `rc(x, y)`: right contraction.
    Rc,
    /// `sp(x, y)`: scalar product.
    Sp,
    /// `comm(x, y)` = (xy - yx)/2.
    Comm,
    /// `acomm(x, y)` = (xy + yx)/2.
    Acomm,
    /// `gp(x, y)`: geometric product.
    Gp,
    /// `op(x, y)`: outer product.
    Op,
    /// `rp(x, y)`: regressive product.
    Rp,
    /// `dual(x)`: the metric-free right complement.
    Dual,
    /// `undual(x)`: the inverse of `dual`.
    Undual,
    /// `involute(x)`: the grade involution.
    Involute,
    /// `conj(x)`: the Clifford conjugate.
    Conj,
    /// `exp(x)` (f64 and mpfr only).
    Exp,
    /// `log(x)` (f64 and mpfr only).
    Log,
    /// `sqrt(x)` (f64 and mpfr only).
    Sqrt,
    /// `diff(x, v)`: the partial derivative by the variable `v` (poly only).
    Diff,
}

/// Every function with its name and parameter names (for arity messages and the docs).
pub const FUNCTIONS: [(Func, &str, &[&str]); 21] = [
    (Func::Rev, "rev", &["x"]),
    (Func::Inv, "inv", &["x"]),
    (Func::Grade, "grade", &["x", "k"]),
    (Func::Lc, "lc", &["x", "y"]),
    (Func::Rc, "rc", &["x", "y"]),
    (Func::Sp, "sp", &["x", "y"]),
    (Func::Comm, "comm", &["x", "y"]),
    (Func::Acomm, "acomm", &["x", "y"]),
    (Func::Dual, "dual", &["x"]),
    (Func::Undual, "undual", &["x"]),
    (Func::Gp, "gp", &["x", "y"]),
    (Func::Op, "op", &["x", "y"]),
    (Func::Rp, "rp", &["x", "y"]),
    (Func::Involute, "involute", &["x"]),
    (Func::Conj, "conj", &["x"]),
    (Func::BasisGrade, "bgrade", &["x", "k"]),
    (Func::BasisRev, "brev", &["x"]),
    (Func::Exp, "exp", &["x"]),
    (Func::Log, "log", &["x"]),
    (Func::Sqrt, "sqrt", &["x"]),
    (Func::Diff, "diff", &["x", "v"]),
];

impl Func {
    /// The function called `name`, if any.
    pub fn from_name(name: &str) -> Option<Func> {
        FUNCTIONS.iter().find(|(_, n, _)| *n == name).map(|(f, _, _)| *f)
    }

    /// The function's name in expressions.
    pub fn name(self) -> &'static str {
        FUNCTIONS.iter().find(|(f, _, _)| *f == self).map(|(_, n, _)| *n).unwrap_or("?")
    }

    fn params(self) -> &'static [&'static str] {
        FUNCTIONS.iter().find(|(f, _, _)| *f == self).map(|(_, _, p)| *p).unwrap_or(&[])
    }
}

/// A prefix operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PrefixOp {
    /// `-x`
    Neg,
    /// `~x`, the reverse.
    Reverse,
}

/// A binary operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`, the geometric product.
    Mul,
    /// `/`, right division by a scalar or an invertible element.
    Div,
    /// `^`, the outer product.
    Wedge,
}

/// A parsed expression. Every node knows the column where it starts (operators: where the
/// operator is), counted in characters from 1.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    /// A number literal, kept as text so each scalar type reads it its own way.
    Number {
        /// The literal.
        text: String,
        /// Its column.
        col: usize,
    },
    /// A basis name, a variable, or a misplaced function name.
    Ident {
        /// The identifier.
        name: String,
        /// Its column.
        col: usize,
    },
    /// `-x` or `~x`.
    Prefix {
        /// The operator.
        op: PrefixOp,
        /// The operand.
        operand: Box<Node>,
        /// The operator's column.
        col: usize,
    },
    /// `first op1 x1 op2 x2 ...` for operators of one precedence level, left-associative.
    Chain {
        /// The first operand.
        first: Box<Node>,
        /// The following operators (with their columns) and operands.
        rest: Vec<(BinOp, usize, Node)>,
    },
    /// `base ** exponent`, a power by a non-negative integer.
    Power {
        /// The base.
        base: Box<Node>,
        /// The exponent.
        exponent: u32,
        /// The column of `**`.
        col: usize,
    },
    /// `f(args...)`, arity already checked.
    Call {
        /// The function.
        func: Func,
        /// The arguments.
        args: Vec<Node>,
        /// The column of the function name.
        col: usize,
    },
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(String),
    Ident(String),
    Sym(char),
    /// `**`.
    Pow,
    End,
}

#[derive(Debug, Clone)]
struct Token {
    tok: Tok,
    col: usize,
}

fn parse_error(col: usize, message: impl std::fmt::Display) -> CliError {
    CliError::usage(format!("parse error at column {col}: {message}"))
}

fn describe(t: &Tok) -> String {
    match t {
        Tok::Num(s) | Tok::Ident(s) => format!("`{s}`"),
        Tok::Sym(c) => format!("`{c}`"),
        Tok::Pow => "`**`".to_string(),
        Tok::End => "end of input".to_string(),
    }
}

/// The length of an exponent `e[+-]digits` / `E[+-]digits` at the start of `rest`, or 0 when
/// there is none (then an `e` after a number starts a name, as before: `2einf` is an error).
fn exponent_len(rest: &[char]) -> usize {
    if !matches!(rest.first(), Some('e' | 'E')) {
        return 0;
    }
    let sign = usize::from(matches!(rest.get(1), Some('+' | '-')));
    let digits = rest[1 + sign..].iter().take_while(|c| c.is_ascii_digit()).count();
    if digits == 0 { 0 } else { 1 + sign + digits }
}

/// `has_element(name)`: whether the algebra has a basis element `name` (for the wording of
/// the `2e5` refusal).
fn tokenize(src: &str, has_element: &dyn Fn(&str) -> bool) -> Result<Vec<Token>, CliError> {
    let chars: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let col = i + 1;
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)) {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            if i < chars.len() && chars[i] == '.' {
                i += 1;
                if !chars.get(i).is_some_and(char::is_ascii_digit) {
                    return Err(parse_error(i + 1, "expected a digit after the decimal point"));
                }
                while i < chars.len() && chars[i].is_ascii_digit() {
                    i += 1;
                }
            }
            if chars.get(i) == Some(&'e') && chars.get(i + 1).is_some_and(char::is_ascii_digit) {
                let digits: String = chars[i + 1..].iter().take_while(|c| c.is_ascii_digit()).collect();
                let number: String = chars[start..i].iter().collect();
                let message = if has_element(&format!("e{digits}")) {
                    format!(
                        "`{number}e{digits}` is ambiguous: write `{number}*e{digits}` for a multiple of the basis element `e{digits}`, or `{number}e+{digits}` / `{number}E{digits}` for the number"
                    )
                } else {
                    format!(
                        "`{number}e{digits}` is refused: write `{number}e+{digits}` or `{number}E{digits}` for the number (a lowercase `e` followed by digits names a basis element, and this algebra has no `e{digits}`)"
                    )
                };
                return Err(parse_error(col, message));
            }
            i += exponent_len(&chars[i..]);
            out.push(Token { tok: Tok::Num(chars[start..i].iter().collect()), col });
        } else if c.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push(Token { tok: Tok::Ident(chars[start..i].iter().collect()), col });
        } else if c == '*' && chars.get(i + 1) == Some(&'*') {
            out.push(Token { tok: Tok::Pow, col });
            i += 2;
        } else if "+-*/^~(),".contains(c) {
            out.push(Token { tok: Tok::Sym(c), col });
            i += 1;
        } else {
            return Err(parse_error(col, format!("unexpected character `{c}`")));
        }
    }
    out.push(Token { tok: Tok::End, col: chars.len() + 1 });
    Ok(out)
}

/// Parses an expression for `algebra` (whose basis names word the refusal of `2e5`).
///
/// Errors (exit status 2) name the column: `parse error at column 7: expected ')'`, or
/// `unknown function `foo` at column 1 (...)`.
pub fn parse(src: &str, algebra: &Algebra) -> Result<Node, CliError> {
    let mut p = Parser { toks: tokenize(src, &|name| algebra.mask_of(name).is_ok())?, pos: 0, depth: 0 };
    let node = p.sum()?;
    let t = p.peek().clone();
    match t.tok {
        Tok::End => Ok(node),
        Tok::Sym(')') => Err(parse_error(t.col, "unmatched `)`")),
        Tok::Pow => Err(parse_error(t.col, "a chain `a**j**k` is ambiguous: write `(a**j)**k` or `a**(j*k)`")),
        Tok::Num(_) | Tok::Ident(_) | Tok::Sym('(') => Err(parse_error(
            t.col,
            format!("expected an operator before {} (products need an explicit `*`)", describe(&t.tok)),
        )),
        other => Err(parse_error(t.col, format!("expected an operator, found {}", describe(&other)))),
    }
}

struct Parser {
    toks: Vec<Token>,
    pos: usize,
    depth: usize,
}

impl Parser {
    fn peek(&self) -> &Token {
        &self.toks[self.pos.min(self.toks.len() - 1)]
    }

    fn next(&mut self) -> Token {
        let t = self.peek().clone();
        if self.pos < self.toks.len() - 1 {
            self.pos += 1;
        }
        t
    }

    fn peek_sym(&self) -> Option<char> {
        match self.peek().tok {
            Tok::Sym(c) => Some(c),
            _ => None,
        }
    }

    fn enter(&mut self, col: usize) -> Result<(), CliError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(parse_error(col, format!("nesting deeper than {MAX_DEPTH} levels")));
        }
        Ok(())
    }

    /// One precedence level of left-associative binary operators.
    fn chain(
        &mut self,
        ops: &[(char, BinOp)],
        operand: fn(&mut Self) -> Result<Node, CliError>,
    ) -> Result<Node, CliError> {
        let first = operand(self)?;
        let mut rest = Vec::new();
        while let Some(&(_, op)) = self.peek_sym().and_then(|c| ops.iter().find(|(s, _)| *s == c)) {
            let col = self.next().col;
            rest.push((op, col, operand(self)?));
        }
        Ok(if rest.is_empty() { first } else { Node::Chain { first: Box::new(first), rest } })
    }

    fn sum(&mut self) -> Result<Node, CliError> {
        self.chain(&[('+', BinOp::Add), ('-', BinOp::Sub)], Self::product)
    }

    fn product(&mut self) -> Result<Node, CliError> {
        self.chain(&[('*', BinOp::Mul), ('/', BinOp::Div)], Self::wedge)
    }

    fn wedge(&mut self) -> Result<Node, CliError> {
        self.chain(&[('^', BinOp::Wedge)], Self::prefix)
    }

    fn prefix(&mut self) -> Result<Node, CliError> {
        let op = match self.peek_sym() {
            Some('-') => PrefixOp::Neg,
            Some('~') => PrefixOp::Reverse,
            _ => return self.power(),
        };
        let col = self.next().col;
        self.enter(col)?;
        let operand = Box::new(self.prefix()?);
        self.depth -= 1;
        Ok(Node::Prefix { op, operand, col })
    }

    fn power(&mut self) -> Result<Node, CliError> {
        let base = self.atom()?;
        if self.peek().tok != Tok::Pow {
            return Ok(base);
        }
        let col = self.next().col;
        let t = self.next();
        let exponent = match &t.tok {
            Tok::Num(text) if text.bytes().all(|b| b.is_ascii_digit()) => {
                text.parse::<u32>().ok().filter(|k| *k <= MAX_EXPONENT).ok_or_else(|| {
                    parse_error(t.col, format!("the exponent `{text}` of `**` is larger than {MAX_EXPONENT}"))
                })?
            }
            other => {
                return Err(parse_error(
                    t.col,
                    format!("the exponent of `**` must be a non-negative integer literal, found {}", describe(other)),
                ));
            }
        };
        Ok(Node::Power { base: Box::new(base), exponent, col })
    }

    fn atom(&mut self) -> Result<Node, CliError> {
        let t = self.next();
        match t.tok {
            Tok::Num(text) => Ok(Node::Number { text, col: t.col }),
            Tok::Ident(name) if self.peek_sym() == Some('(') => self.call(name, t.col),
            Tok::Ident(name) => Ok(Node::Ident { name, col: t.col }),
            Tok::Sym('(') => {
                self.enter(t.col)?;
                let inner = self.sum()?;
                self.expect(')', "`)`")?;
                self.depth -= 1;
                Ok(inner)
            }
            other => Err(parse_error(t.col, format!("expected an expression, found {}", describe(&other)))),
        }
    }

    fn expect(&mut self, c: char, what: &str) -> Result<(), CliError> {
        let t = self.next();
        if t.tok == Tok::Sym(c) {
            Ok(())
        } else {
            Err(parse_error(t.col, format!("expected {what}, found {}", describe(&t.tok))))
        }
    }

    fn call(&mut self, name: String, col: usize) -> Result<Node, CliError> {
        let Some(func) = Func::from_name(&name) else {
            let known: Vec<&str> = FUNCTIONS.iter().map(|(_, n, _)| *n).collect();
            return Err(CliError::usage(format!(
                "unknown function `{name}` at column {col} (functions: {})",
                known.join(", ")
            )));
        };
        self.next(); // '('
        self.enter(col)?;
        let mut args = Vec::new();
        if self.peek_sym() != Some(')') {
            args.push(self.sum()?);
            while self.peek_sym() == Some(',') {
                self.next();
                args.push(self.sum()?);
            }
        }
        self.expect(')', "`,` or `)`")?;
        self.depth -= 1;
        let params = func.params();
        if args.len() != params.len() {
            return Err(CliError::usage(format!(
                "`{name}` at column {col} takes {} argument{} ({name}({})), got {}",
                params.len(),
                if params.len() == 1 { "" } else { "s" },
                params.join(", "),
                args.len()
            )));
        }
        Ok(Node::Call { func, args, col })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn show(n: &Node) -> String {
        match n {
            Node::Number { text, .. } => text.clone(),
            Node::Ident { name, .. } => name.clone(),
            Node::Prefix { op, operand, .. } => {
                format!("({}{})", if *op == PrefixOp::Neg { "-" } else { "~" }, show(operand))
            }
            Node::Chain { first, rest } => {
                let mut s = show(first);
                for (op, _, x) in rest {
                    let o = match op {
                        BinOp::Add => "+",
                        BinOp::Sub => "-",
                        BinOp::Mul => "*",
                        BinOp::Div => "/",
                        BinOp::Wedge => "^",
                    };
                    s = format!("({s}{o}{})", show(x));
                }
                s
            }
            Node::Call { func, args, .. } => {
                format!("{}({})", func.name(), args.iter().map(show).collect::<Vec<_>>().join(","))
            }
            Node::Power { base, exponent, .. } => format!("({}**{exponent})", show(base)),
        }
    }

    /// [`super::parse`] in g3 (basis elements `e1`, `e2`, `e3`, `e12`, ...).
    fn parse(src: &str) -> Result<Node, CliError> {
        super::parse(src, &Algebra::builtin("g3").unwrap())
    }

    fn err(src: &str) -> String {
        parse(src).unwrap_err().message
    }

    #[test]
    fn precedence() {
        assert_eq!(show(&parse("a + b*c^d").unwrap()), "(a+(b*(c^d)))");
        assert_eq!(show(&parse("-a^b").unwrap()), "((-a)^b)");
        assert_eq!(show(&parse("~a^b*c").unwrap()), "(((~a)^b)*c)");
        assert_eq!(show(&parse("a-b-c").unwrap()), "((a-b)-c)");
        assert_eq!(show(&parse("a^b^c").unwrap()), "((a^b)^c)");
        assert_eq!(show(&parse("1/2*e1").unwrap()), "((1/2)*e1)");
        assert_eq!(show(&parse("grade(e1 + 2, 0.5)").unwrap()), "grade((e1+2),0.5)");
        assert_eq!(show(&parse("--e1").unwrap()), "(-(-e1))");
    }

    #[test]
    fn powers_bind_tighter_than_prefixes_and_products() {
        assert_eq!(show(&parse("-x**2").unwrap()), "(-(x**2))");
        assert_eq!(show(&parse("2*S12**2 - y**3").unwrap()), "((2*(S12**2))-(y**3))");
        assert_eq!(show(&parse("a^b**2").unwrap()), "(a^(b**2))");
        assert_eq!(show(&parse("(e1+e2)**0").unwrap()), "((e1+e2)**0)");
        assert_eq!(show(&parse("~x**2*y").unwrap()), "((~(x**2))*y)");
        assert_eq!(show(&parse("rev(x)**2").unwrap()), "(rev(x)**2)");
        assert_eq!(
            err("x**-1"),
            "parse error at column 4: the exponent of `**` must be a non-negative integer literal, found `-`"
        );
        assert_eq!(
            err("x**0.5"),
            "parse error at column 4: the exponent of `**` must be a non-negative integer literal, found `0.5`"
        );
        assert_eq!(
            err("x**y"),
            "parse error at column 4: the exponent of `**` must be a non-negative integer literal, found `y`"
        );
        assert!(err("x**2**3").starts_with("parse error at column 5: a chain `a**j**k` is ambiguous"));
        assert!(err("x**99999999999").contains("larger than 1000000000"));
        assert!(err("x**").contains("found end of input"));
        assert_eq!(err("x * *y"), "parse error at column 5: expected an expression, found `*`");
    }

    #[test]
    fn errors_have_columns() {
        assert_eq!(err("e1 * (e2 + "), "parse error at column 12: expected an expression, found end of input");
        assert_eq!(err("(e1 + e2"), "parse error at column 9: expected `)`, found end of input");
        assert_eq!(err("e1 $ e2"), "parse error at column 4: unexpected character `$`");
        assert_eq!(err("e1)"), "parse error at column 3: unmatched `)`");
        assert!(err("2e1").starts_with("parse error at column 1: `2e1` is ambiguous"));
        assert_eq!(
            err("2e5"),
            "parse error at column 1: `2e5` is refused: write `2e+5` or `2E5` for the number (a lowercase `e` followed by digits names a basis element, and this algebra has no `e5`)"
        );
        let cga = Algebra::builtin("cga").unwrap();
        assert!(
            super::parse("2e5", &cga).unwrap_err().message.contains("`2*e5` for a multiple of the basis element `e5`")
        );
        assert!(err("2 e1").contains("column 3"));
        assert!(err("1.").contains("column 3"));
        assert!(err("foo(e1)").starts_with("unknown function `foo` at column 1"));
        assert!(err("x + grade(e1)").starts_with("`grade` at column 5 takes 2 arguments"));
        assert!(err("").contains("column 1"));
        assert!(err(&"(".repeat(300)).contains("nesting"));
        assert!(err(&"-".repeat(300)).contains("nesting"));
    }

    #[test]
    fn columns_count_characters() {
        assert_eq!(err("\u{a0}\u{a0}e1 $"), "parse error at column 6: unexpected character `$`");
        assert_eq!(err("é"), "parse error at column 1: unexpected character `é`");
    }
}
