//! `gam`: the GAM command line (see docs/cli.md and the contract in shared/cli.md).
//!
//! This file only parses arguments (clap), dispatches to the commands of the `gam` library
//! (cli/src/lib.rs, which the Python package calls too), and maps failures to exit statuses:
//! 2 for bad usage or input, 1 for a mathematical failure, each with exactly one `error:` line
//! on stderr and nothing on stdout.

use gam::{
    algebra_help, codegen, commands, error, figures, finite_guard, hermite, interpolate, plot, pose, precision, prove,
    sample, scalar, surface, trajectory, verify,
};

use algebra_core::{Basis, Product};
use clap::error::ErrorKind;
use clap::{Parser, Subcommand};
use error::{CliError, EXIT_USAGE};
use precision::MotionScalar;
use scalar::ScalarKind;
use std::io::Write;
use std::process::ExitCode;

/// Exact geometric algebra from the command line: evaluate expressions, print product tables.
#[derive(Debug, Parser)]
#[command(name = "gam", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// List the built-in algebras (or the named ones) with their labels and metrics.
    Algebras {
        /// Print one JSON list.
        #[arg(long)]
        json: bool,
        /// Built-in names or TOML files to describe instead of all built-ins.
        #[arg(value_name = "ALGEBRA")]
        algebras: Vec<String>,
    },
    /// Evaluate a multivector expression.
    Eval {
        #[arg(long, value_name = "NAME", default_value = "cga-null", help = algebra_help())]
        algebra: String,
        /// The basis for reading and printing basis names: blade or product.
        #[arg(long, value_name = "B", default_value = "blade")]
        basis: Basis,
        /// rational (exact), poly (symbolic), f64, or mpfr:BITS.
        #[arg(long, value_name = "S", default_value = "rational")]
        scalar: ScalarKind,
        /// Print the result as one JSON object.
        #[arg(long)]
        json: bool,
        /// The expression, e.g. "e1*e2*e3*einf*e0" (may start with `-`); `@FILE` reads it from
        /// FILE and `-` from stdin.
        #[arg(allow_hyphen_values = true, value_name = "EXPR")]
        expr: String,
    },
    /// Print the table of a product on the basis elements.
    Table {
        #[arg(long, value_name = "NAME", default_value = "cga-null", help = algebra_help())]
        algebra: String,
        /// The basis: blade or product.
        #[arg(long, value_name = "B", default_value = "blade")]
        basis: Basis,
        /// gp, op, lc, rc, sp, rp, comm or acomm.
        #[arg(long, value_name = "P", default_value = "gp")]
        product: Product,
        /// Print a JSON list of {"a", "b", "result"}.
        #[arg(long)]
        json: bool,
    },
    /// Generate the Rust module of the `algebra!` macro (or its kernels' operation counts).
    Codegen(codegen::CodegenArgs),
    /// Control poses of a motion segment from its end conditions (Secs. 4-5 of the main paper).
    Hermite {
        /// Print one JSON object: {"control_poses", "velocity_bivectors", "velocity_indicatrices"}.
        #[arg(long)]
        json: bool,
        /// The JSON spec: kind, degree, start and end conditions (see docs/cli.md).
        #[arg(value_name = "SPEC.json")]
        spec: String,
        /// f64 or mpfr:BITS (rational exits 2: the end rotations are axis and angle).
        #[arg(long, value_name = "S", default_value = "f64")]
        scalar: MotionScalar,
    },
    /// A motion through key poses by a named method: ccm-additive, ccm-multiplicative,
    /// wl-linear, wl-quadratic, wl-direct, hexanion-linear, hexanion-decoupled, hexanion-blend,
    /// juttler-q-motion, juttler-affine, juttler-projective, juttler-trt, juttler-minimal,
    /// juttler-spline, juttler-bspline, juttler-minimal-spline (docs/cli.md, "gam interpolate").
    Interpolate {
        /// Print one JSON object: {"method", "parameters", "segments", "samples"}.
        #[arg(long)]
        json: bool,
        /// The JSON spec: method, poses, optional parameters, velocities, shape, gamma, samples,
        /// body_points (see docs/cli.md).
        #[arg(value_name = "SPEC.json")]
        spec: String,
        /// f64, rational (exact: juttler-* methods with rational key poses) or mpfr:BITS.
        #[arg(long, value_name = "S", default_value = "f64")]
        scalar: MotionScalar,
    },
    /// The trajectory of a body point under a `gam interpolate` spec's motion as rational Bézier
    /// curves, one per segment (rational methods only: ccm-additive, juttler-*).
    Trajectory {
        /// Print one JSON object: {"segments": [{"t0", "t1", "degree", "weights", "points"}]}.
        #[arg(long)]
        json: bool,
        /// f64, rational (exact: juttler-* methods with rational key poses) or mpfr:BITS.
        #[arg(long, value_name = "S", default_value = "f64")]
        scalar: MotionScalar,
        /// The JSON spec of `gam interpolate`.
        #[arg(value_name = "SPEC.json")]
        spec: String,
        /// The body point, in body coordinates.
        #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
        point: String,
    },
    /// The kinematic (sweep) surface of a rational curve of the body under a `gam interpolate`
    /// spec's motion, as rational tensor-product Bézier patches, one per segment (rational
    /// methods only: ccm-additive, juttler-*).
    Surface {
        /// Print one JSON object: {"segments": [{"t0", "t1", "degrees", "weights", "points"}]}.
        #[arg(long)]
        json: bool,
        /// The JSON spec of `gam interpolate`.
        #[arg(value_name = "SPEC.json")]
        spec: String,
        /// The curve: a JSON file {"points": [[x, y, z], ...], "weights": [w, ...]} (body coordinates).
        #[arg(long, value_name = "CURVE.json")]
        curve: String,
        /// f64, rational (exact: juttler-* methods with rational key poses) or mpfr:BITS.
        #[arg(long, value_name = "S", default_value = "f64")]
        scalar: MotionScalar,
    },
    /// One pose in every representation: matrix, quaternion, axis-angle, motor, dual quaternion,
    /// hexanion, screw.
    Pose {
        /// Print one JSON object with the keys of docs/cli.md.
        #[arg(long)]
        json: bool,
        /// A pose object (JSON, any form of `gam interpolate`'s poses), or @FILE.
        #[arg(value_name = "POSE_JSON", allow_hyphen_values = true)]
        pose: String,
        /// f64, rational (exact: matrix and position only) or mpfr:BITS.
        #[arg(long, value_name = "S", default_value = "f64")]
        scalar: MotionScalar,
    },
    /// Sample a `gam hermite` segment: pose, body point position, linear and angular speed.
    Sample {
        /// The number of evenly spaced parameter values t = 0..1 (at least 2).
        #[arg(long, value_name = "N")]
        samples: usize,
        /// Print one JSON object: {"samples": [{"t", "pose", "position", "linear_speed", "angular_speed"}]}.
        #[arg(long)]
        json: bool,
        /// The JSON spec of `gam hermite`, plus an optional "body_point": [x, y, z].
        #[arg(value_name = "SPEC.json")]
        spec: String,
        /// f64, mpfr:BITS, or rational (exact poses and positions, speeds left out; gam
        /// interpolate specs of the juttler-* methods).
        #[arg(long, value_name = "S", default_value = "f64")]
        scalar: MotionScalar,
    },
    /// Plot specs to SVG (or PNG): speeds against t with the joins marked, and the paths of the body
    /// points (several specs are overlaid with a legend).
    Plot {
        /// The file to write: SVG, or PNG when its name ends in `.png` (see `--format`).
        #[arg(long, value_name = "FILE.svg")]
        out: String,
        /// The file format (default: png for an --out ending in .png, svg otherwise).
        #[arg(long, value_name = "FORMAT", value_enum)]
        format: Option<plot::Format>,
        /// The number of evenly spaced parameter values over each spec's range (at least 2).
        #[arg(long, value_name = "N", default_value_t = plot::DEFAULT_SAMPLES)]
        samples: usize,
        /// The path panel: a projection on the x-y, x-z or y-z plane, or a 3-D view.
        #[arg(long, value_name = "VIEW", value_enum, default_value = "xy")]
        view: plot::View,
        /// Draw the moved body's coordinate frames at K evenly spaced parameters.
        #[arg(long, value_name = "K", default_value_t = 0)]
        frames: usize,
        /// How the body is drawn at the frames: its coordinate frame, the unit cube, the L-shaped block or the cuboid.
        #[arg(long, value_name = "BODY", value_enum, default_value = "frames")]
        body: plot::Body,
        /// Also print the data of the figure as one JSON object {"title", "series": [...]}.
        #[arg(long)]
        json: bool,
        /// Animate the body along its path with a cursor on the speed panel: an animated SVG,
        /// or an HTML page with play/pause and a slider when --out ends in .html.
        #[arg(long)]
        animate: bool,
        /// Draw the linear and angular accelerations |a|, |Omega'| instead of the speeds (not
        /// with --animate).
        #[arg(long, conflicts_with = "animate")]
        acceleration: bool,
        /// `gam interpolate` specs (with "method") or `gam hermite` specs (with an optional
        /// "body_point": [x, y, z]).
        #[arg(value_name = "SPEC.json", required = true)]
        specs: Vec<String>,
    },
    /// Regenerate the papers' figures (main paper Figs. 3-10, Wareham–Lasenby Figs. 5 and 7, Jüttler Figs. 1-6) as SVG files in DIR.
    Figures {
        /// The directory to write fig3.svg, fig4.svg, fig5.svg into.
        #[arg(long, value_name = "DIR")]
        out: String,
        /// The file format of the figures (their names end in .svg or .png).
        #[arg(long, value_name = "FORMAT", value_enum, default_value = "svg")]
        format: plot::Format,
        /// Also print the data of the figures as one JSON object keyed by file name.
        #[arg(long)]
        json: bool,
    },
    /// Decide a polynomial identity symbolically under hypotheses (ideal membership over Q).
    Prove {
        /// A built-in algebra (g3, g123inf, pga3, cga, cga-null) or a path to a TOML file.
        #[arg(long, value_name = "NAME", default_value = "cga-null")]
        algebra: String,
        /// The basis for basis names and builders: blade or product.
        #[arg(long, value_name = "B", default_value = "blade")]
        basis: Basis,
        /// A hypothesis `EXPR = EXPR` (component-wise) or `EXPR != 0` (scalar); repeatable.
        #[arg(long, value_name = "EQ", allow_hyphen_values = true)]
        assume: Vec<String>,
        /// Give up with "undecided" (exit 1) after this many seconds.
        #[arg(long, value_name = "SECONDS", default_value_t = 10.0)]
        timeout: f64,
        /// Give up with "undecided" (exit 1) when the Gröbner basis would hold more polynomials.
        #[arg(long, value_name = "N", default_value_t = algebra_core::ideal::Budget::default().max_basis)]
        max_basis: usize,
        /// Give up with "undecided" (exit 1) when an intermediate polynomial would have more
        /// terms, or all of them together more than 20 times as many.
        #[arg(long, value_name = "N", default_value_t = algebra_core::ideal::Budget::default().max_terms)]
        max_terms: usize,
        /// Print one JSON object: {"holds", "method", "basis_size", "time_ms", "witness", ...}.
        #[arg(long)]
        json: bool,
        /// `[let NAME = EXPR;]... EXPR = EXPR`, with builders even("P"), odd("P"), vector("P"),
        /// grade("P", k), all("P").
        #[arg(allow_hyphen_values = true, value_name = "CLAIM")]
        claim: String,
    },
    /// Check the papers' numbered statements (lemmas, theorems, equations) and report each.
    Verify {
        /// Print a JSON list of {"id", "paper", "label", "statement", "method", "holds",
        /// "checks", "failures", "note", "time_ms"}.
        #[arg(long)]
        json: bool,
        /// Only the statements whose id, label, paper or method contains TEXT (case-insensitive).
        #[arg(long, value_name = "TEXT")]
        filter: Option<String>,
        /// List the selected statements (id, label, paper, method; with --json also the
        /// statement and its hypotheses) without running them.
        #[arg(long)]
        list: bool,
    },
}

/// Runs a command: its output and, for `verify`, the failure to report after printing it.
fn run(command: Command) -> Result<(String, Option<CliError>), CliError> {
    let done = |out: String| (out, None);
    // the numeric commands' last guard (finite_guard): one place for all of them; the streamed
    // outputs (`sample`, `--json` samples) are checked sample by sample instead
    let guarded = match &command {
        Command::Eval { .. } => Some("eval"),
        Command::Hermite { .. } => Some("hermite"),
        Command::Interpolate { .. } => Some("interpolate"),
        Command::Trajectory { .. } => Some("trajectory"),
        Command::Surface { .. } => Some("surface"),
        Command::Pose { .. } => Some("pose"),
        Command::Sample { .. } => Some("sample"),
        _ => None,
    };
    let out = match command {
        Command::Algebras { json, algebras } => commands::algebras(&algebras, json),
        Command::Eval { algebra, basis, scalar, json, expr } => {
            if let Some(result) = prove::eval_relation(&algebra, basis, &scalar, json, &expr) {
                return result;
            }
            commands::eval(&commands::EvalArgs { algebra, basis, scalar, json, expr })
        }
        Command::Table { algebra, basis, product, json } => commands::table(&algebra, basis, product, json),
        Command::Codegen(args) => codegen::codegen(&args),
        Command::Hermite { json, spec, scalar } => hermite::hermite(&spec, json, scalar),
        Command::Interpolate { json, spec, scalar } => interpolate::interpolate(&spec, json, scalar),
        Command::Trajectory { json, spec, point, scalar } => trajectory::trajectory(&spec, &point, json, scalar),
        Command::Surface { json, spec, curve, scalar } => surface::surface(&spec, &curve, json, scalar),
        Command::Pose { json, pose, scalar } => pose::pose(&pose, json, scalar),
        Command::Sample { samples, json, spec, scalar } => sample::sample(&spec, samples, json, scalar),
        Command::Plot { out, format, samples, view, frames, body, json, animate, acceleration, specs } => {
            let (specs, out) = (&specs, &out);
            plot::plot(&plot::PlotArgs { specs, out, format, samples, view, frames, body, json, animate, acceleration })
        }
        Command::Figures { out, format, json } => figures::figures(&out, format, json),
        Command::Prove { algebra, basis, assume, timeout, max_basis, max_terms, json, claim } => {
            let args = prove::ProveArgs { algebra, basis, assume, timeout, max_basis, max_terms, json, claim };
            return prove::prove(&args);
        }
        Command::Verify { json, filter, list: true } => verify::list(filter.as_deref(), json),
        Command::Verify { json, filter, list: false } => {
            return verify::verify(filter.as_deref(), json).map(|v| (v.output, v.failure));
        }
    };
    match guarded {
        Some(name) => out.and_then(|out| finite_guard::finite_output(name, out)).map(done),
        None => out.map(done),
    }
}

/// clap's error as one `error:` line (help and version requests are printed as usual).
fn clap_failure(e: clap::Error) -> ExitCode {
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        let _ = e.print();
        return ExitCode::SUCCESS;
    }
    let text = e.render().to_string();
    let line = match e.kind() {
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand | ErrorKind::MissingSubcommand => {
            "error: a subcommand is required: algebras, eval, table, codegen, hermite, interpolate, trajectory, surface, pose, sample, plot, figures, prove or verify (see gam --help)"
                .to_string()
        }
        _ => first_error_line(&text),
    };
    eprintln!("{line}");
    ExitCode::from(EXIT_USAGE)
}

/// The `error:` line of a rendered clap error, with an indented continuation (such as the
/// missing `<EXPR>` after "the following required arguments were not provided:") joined on.
fn first_error_line(text: &str) -> String {
    let mut lines = text.lines().skip_while(|l| !l.starts_with("error:"));
    let Some(first) = lines.next() else {
        return format!("error: {}", text.lines().next().unwrap_or("invalid arguments"));
    };
    let mut line = first.trim_end().to_string();
    if line.ends_with(':') {
        for more in lines.take_while(|l| l.starts_with(' ') && !l.trim().is_empty()) {
            line.push(' ');
            line.push_str(more.trim());
        }
    }
    line
}

/// Rejects unknown `--options` of `gam eval` before clap sees them: EXPR accepts values that
/// start with `-` (so `gam eval "-e1"` works), which would otherwise swallow a mistyped option.
fn check_eval_options(args: &[String]) -> Result<(), String> {
    let Some(at) = args.iter().skip(1).position(|a| a == "eval") else {
        return Ok(());
    };
    let cmd = <Cli as clap::CommandFactory>::command();
    let known: Vec<String> = cmd
        .find_subcommand("eval")
        .map(|sub| sub.get_arguments().filter_map(|a| a.get_long().map(str::to_string)).collect())
        .unwrap_or_default();
    for arg in args.iter().skip(at + 2).take_while(|a| *a != "--") {
        let Some(long) = arg.strip_prefix("--") else { continue };
        let name = long.split('=').next().unwrap_or(long);
        let is_option = name.starts_with(|c: char| c.is_ascii_alphabetic());
        if is_option && !known.iter().any(|k| k == name) && name != "help" && name != "version" {
            return Err(format!(
                "error: unexpected argument '--{name}' found (an expression starting with `--` must come after `--`)"
            ));
        }
    }
    Ok(())
}

/// True when the process started with its standard output closed (`gam eval e1 >&-`): the
/// output would be lost with exit 0. Rust's runtime reopens a closed descriptor 0-2 on
/// `/dev/null` *read-write* before `main` (a shell's `> /dev/null` opens it write-only), so
/// on Linux that is what is looked for (`/proc/self/fd/1`, `/proc/self/fdinfo/1`); elsewhere,
/// a descriptor that cannot be duplicated.
fn stdout_is_closed() -> bool {
    use std::os::fd::AsFd;
    if std::io::stdout().as_fd().try_clone_to_owned().is_err() {
        return true;
    }
    let Ok(target) = std::fs::read_link("/proc/self/fd/1") else { return false };
    let Ok(info) = std::fs::read_to_string("/proc/self/fdinfo/1") else { return false };
    // `flags:` in octal; the access mode is its low two bits (O_RDWR = 2)
    let flags = info.lines().find_map(|l| l.strip_prefix("flags:")).and_then(|f| u32::from_str_radix(f.trim(), 8).ok());
    target == std::path::Path::new("/dev/null") && flags.is_some_and(|f| f & 3 == 2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args_os().map(|a| a.to_string_lossy().into_owned()).collect();
    if stdout_is_closed() {
        eprintln!("error: cannot write the output: standard output is closed");
        return ExitCode::from(EXIT_USAGE);
    }
    if let Err(line) = check_eval_options(&args) {
        eprintln!("{line}");
        return ExitCode::from(EXIT_USAGE);
    }
    let cli = match Cli::try_parse_from(&args) {
        Ok(cli) => cli,
        Err(e) => return clap_failure(e),
    };
    match run(cli.command) {
        Ok((out, failure)) => {
            let mut stdout = std::io::stdout().lock();
            match writeln!(stdout, "{out}").and_then(|()| stdout.flush()) {
                Ok(()) => match failure {
                    None => ExitCode::SUCCESS,
                    Some(e) => {
                        eprintln!("error: {e}");
                        ExitCode::from(e.code)
                    }
                },
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: cannot write the output: {e}");
                    ExitCode::from(EXIT_USAGE)
                }
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.code)
        }
    }
}
