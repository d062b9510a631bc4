//! The command line, as clap reads it. DESIGN.md's contract: exit 0 on
//! success, 1 when the input has errors, 2 on usage or I/O errors.

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

#[derive(Parser, Debug)]
#[command(
    name = "cncc",
    version,
    about = "A compiler for CNC milling part programs"
)]
pub struct Cli {
    /// Load a dialect spec (XML) in addition to the built-in ones; it may
    /// extend a built-in dialect. Repeatable.
    #[arg(long = "dialect-file", global = true, value_name = "SPEC.xml")]
    pub dialect_files: Vec<PathBuf>,

    /// A folder of post templates (NAME.j2) that override the target's
    /// built-in ones file by file, wherever a program is posted (post,
    /// port --features, running STEP-NC). See docs/posts.md.
    #[arg(long = "post-dir", global = true, value_name = "DIR")]
    pub post_dir: Option<PathBuf>,

    /// Colour in diagnostics.
    #[arg(long, global = true, value_enum, default_value_t = ColorChoice::Auto)]
    pub color: ColorChoice,

    #[command(subcommand)]
    pub command: Command,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    Auto,
    Always,
    Never,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Human,
    Json,
    /// SARIF 2.1.0, one document on stdout (`check`; elsewhere on stderr).
    Sarif,
}

/// Lint rule selection on the command line (after `cncc.toml`'s).
#[derive(Args, Debug, Default, Clone)]
pub struct LintArgs {
    /// Lint rules to run instead of the configured set: codes, prefixes
    /// (`W07`), names or ALL, comma-separated.
    #[arg(long, value_delimiter = ',', value_name = "RULES")]
    pub select: Option<Vec<String>>,
    /// Lint rules to run besides the configured set.
    #[arg(long = "extend-select", value_delimiter = ',', value_name = "RULES")]
    pub extend_select: Vec<String>,
    /// Lint rules not to run.
    #[arg(long, value_delimiter = ',', value_name = "RULES")]
    pub ignore: Vec<String>,
    /// Run no lint rule (only what the language and the run refuse).
    #[arg(long = "no-lint")]
    pub no_lint: bool,
}

impl LintArgs {
    pub fn selection(&self) -> crate::lint::CliSelect {
        crate::lint::CliSelect {
            select: self.select.clone(),
            extend_select: self.extend_select.clone(),
            ignore: self.ignore.clone(),
        }
    }
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Check programs: exit 0 when clean, 1 when errors were found.
    Check {
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// The dialect (id or alias); detected from each file when absent.
        #[arg(long)]
        dialect: Option<String>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        /// Say which dialect was detected even when the file is clean.
        #[arg(long, short)]
        verbose: bool,
        /// A tool table in LinuxCNC's .tbl format, for running the program.
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// Only read the program (syntax, words, structure): do not run it.
        #[arg(long = "no-run")]
        no_run: bool,
        /// The stock, LxWxH[+X+Y+Z] (mm): simulate the material and report
        /// rapids that cut into it (E1001).
        #[arg(long, value_name = "LxWxH[+X+Y+Z]")]
        stock: Option<String>,
        #[command(flatten)]
        lint: LintArgs,
        #[command(flatten)]
        config: ConfigArgs,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Print the meta-model of a program as readable text.
    Ir {
        file: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
    },
    /// Write a program in another (or its own) dialect.
    Port {
        file: PathBuf,
        /// The target dialect.
        #[arg(long)]
        to: String,
        /// The source dialect; detected when absent.
        #[arg(long)]
        from: Option<String>,
        /// Write here (whole or not at all) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Renumber tools: `OLD=NEW` pairs (`1=5,2=7`) or a file of them.
        #[arg(long = "tool-map", value_name = "MAP")]
        tool_map: Option<String>,
        /// Fallback: write every canned cycle as the moves it makes.
        #[arg(long = "expand-cycles")]
        expand_cycles: bool,
        /// Refuse what the target has no form for instead of writing it as
        /// the moves it makes (see `cncc explain W0612`).
        #[arg(long)]
        strict: bool,
        /// Run both programs and compare their cutting moves (with
        /// --features: their features); exit 1 if they differ.
        #[arg(long)]
        verify: bool,
        /// With --verify: also cut the stock with both programs and compare
        /// the finished parts (always done with --features); exit 1 if they
        /// differ by more than 0.01 mm.
        #[arg(long, requires = "verify")]
        material: bool,
        /// Raise to STEP-NC features (CC2) and post them with the target's
        /// feature cycles (POCKET1, CYCLE71, CYCL DEF ...).
        #[arg(long, conflicts_with = "expand_cycles")]
        features: bool,
        /// With --features or --material: a tool table in LinuxCNC's .tbl
        /// format (tool geometry).
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// With --features or --material: the stock block, mm:
        /// `LxWxH[+X+Y+Z]` (else the program's BLK FORM, else round the
        /// feed moves).
        #[arg(long, value_name = "LxWxH[+X+Y+Z]")]
        stock: Option<String>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Post a STEP-NC feature file (ISO 14649) as a program for a target
    /// dialect, with the target's canned cycles.
    Post {
        file: PathBuf,
        /// The target dialect.
        #[arg(long)]
        to: String,
        /// Write here (whole or not at all) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        /// Read a profile whose placement repeats its feature's (some
        /// generators write the absolute position twice) as placed at the
        /// feature's origin, instead of adding the two as ISO 14649-10 says.
        #[arg(long = "profiles-absolute")]
        profiles_absolute: bool,
        /// List what each workingstep was posted as (the target's cycle,
        /// explicit moves) on stdout; the program goes to `-o` only.
        #[arg(long)]
        summary: bool,
    },
    /// Run a program and print its canonical machining calls, one per line,
    /// as LinuxCNC's rs274 prints them.
    Canon {
        file: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        /// A tool table in LinuxCNC's .tbl format (a built-in T1-T20 table otherwise).
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        config: ConfigArgs,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Raise a program to STEP-NC (ISO 14649 Part 21): CC1 explicit
    /// toolpaths (the default) or CC2 machining features.
    Stepnc {
        file: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        /// A tool table in LinuxCNC's .tbl format: tool geometry (a built-in T1-T20 table otherwise).
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// The stock block, mm: `LxWxH[+X+Y+Z]` (sizes, then the lowest corner; default top at Z0, corner at X0 Y0). Without it, a Heidenhain `BLK FORM 0.1/0.2` gives the stock.
        #[arg(long, value_name = "LxWxH[+X+Y+Z]")]
        stock: Option<String>,
        /// Explicit toolpaths (the default).
        #[arg(long, conflicts_with = "cc2")]
        cc1: bool,
        /// Machining features.
        #[arg(long)]
        cc2: bool,
        /// Print a readable listing of the project instead of Part 21.
        #[arg(long)]
        summary: bool,
        /// Write here (whole or not at all) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Machining statistics per tool and in total: cutting and rapid
    /// lengths, estimated time, the box of the cutting moves, the Z range.
    Stats {
        file: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        /// A tool table in LinuxCNC's .tbl format (for the tool diameters).
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// Rapid traverse rate for the time estimate, mm/min.
        #[arg(long = "rapid-rate", value_name = "MM/MIN", default_value_t = 10000.0)]
        rapid_rate: f64,
        /// Seconds per tool change for the time estimate.
        #[arg(long = "tool-change-time", value_name = "S", default_value_t = 5.0)]
        tool_change_time: f64,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        run: RunArgs,
    },
    /// The semantic difference of two programs (any dialects): cutting
    /// moves, holes, tools, feeds and speeds; exit 0 when they cut the
    /// same, 1 when not.
    Diff {
        a: PathBuf,
        b: PathBuf,
        /// The dialect of A (detected when absent).
        #[arg(long = "dialect-a")]
        dialect_a: Option<String>,
        /// The dialect of B (detected when absent).
        #[arg(long = "dialect-b")]
        dialect_b: Option<String>,
        /// How far apart two points may be and still be the same, mm.
        #[arg(long, default_value_t = 0.001)]
        tolerance: f64,
        /// Do not compare feeds, spindle speeds and dwells.
        #[arg(long = "no-feeds")]
        no_feeds: bool,
        /// Also list rapids that differ (never a difference in the verdict).
        #[arg(long)]
        rapids: bool,
        /// Compare the parts the two programs cut (material simulation)
        /// instead of their moves.
        #[arg(long)]
        material: bool,
        /// With --material: the stock, LxWxH[+X+Y+Z] (mm).
        #[arg(long, value_name = "LxWxH[+X+Y+Z]")]
        stock: Option<String>,
        /// With --material: grid cell size, mm.
        #[arg(long, value_name = "MM")]
        resolution: Option<f64>,
        /// With --material: heights within this many mm are the same.
        #[arg(long = "material-tolerance", value_name = "MM", default_value_t = 0.01)]
        material_tolerance: f64,
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Draw toolpaths as SVG or PNG: top (XY), side (XZ) and isometric
    /// views; two files are overlaid with their differences marked.
    Plot {
        #[arg(required = true, num_args = 1..=2)]
        files: Vec<PathBuf>,
        /// The picture to write: .svg or .png.
        #[arg(short, long)]
        output: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        /// Views to draw, in order: top, side, iso.
        #[arg(long, value_delimiter = ',', default_value = "top,side")]
        views: Vec<String>,
        /// The stock: LxWxH[+X+Y+Z] (mm; corner default 0, 0, -H).
        #[arg(long)]
        stock: Option<String>,
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// Picture width in pixels (the height follows).
        #[arg(long, default_value_t = 1200)]
        width: u32,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Set-points for a controller's position loop at a fixed sampling
    /// period (trapezoidal or jerk-limited feed profile, planned over a
    /// look-ahead window of moves), or reference pulses per axis and period at the BLU resolution.
    Interpolate {
        file: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// Sampling period: 1ms, 250us, 0.002s.
        #[arg(long, default_value = "1ms")]
        period: String,
        /// Basic length unit (one pulse), mm.
        #[arg(long, default_value_t = 0.001)]
        blu: f64,
        /// Path acceleration and deceleration, mm/s² (0: no limit).
        #[arg(long, default_value_t = 1000.0)]
        accel: f64,
        /// Path jerk, mm/s³: a jerk-limited (S-curve) profile instead of
        /// the trapezoid (0: no limit, the trapezoid).
        #[arg(long, default_value_t = 0.0)]
        jerk: f64,
        /// Rapid traverse rate, mm/min.
        #[arg(long = "rapid-rate", value_name = "MM/MIN", default_value_t = 10000.0)]
        rapid_rate: f64,
        /// Moves planned ahead of the one running (0: none, every move
        /// starts and ends at rest).
        #[arg(long, value_name = "N", default_value_t = 64)]
        lookahead: usize,
        /// Corner tolerance δ of the junction deviation model, mm: corners
        /// are passed at √(a·δ·sin(θ/2)/(1−sin(θ/2))) (0: stop at every corner).
        #[arg(long = "corner-tolerance", value_name = "MM", default_value_t = 0.01)]
        corner_tolerance: f64,
        /// csv: t,x,y,z,speed per period; pulses: period,x,y,z pulse counts.
        #[arg(long, value_enum, default_value_t = crate::cli::interpolate::Form::Csv)]
        format: crate::cli::interpolate::Form,
        /// Write here (whole or not at all) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Simulate the material a 3-axis program removes: the volume per
    /// tool, the machining time, the cut part as a shaded top view (.png)
    /// or a mesh (.stl); rapids through the material are errors (E1001).
    Simulate {
        file: PathBuf,
        #[arg(long)]
        dialect: Option<String>,
        /// The stock: LxWxH[+X+Y+Z] (mm; corner default 0, 0, -H). Without
        /// it, the program's BLK FORM, else a box round the feed moves.
        #[arg(long, value_name = "LxWxH[+X+Y+Z]")]
        stock: Option<String>,
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        /// Grid cell size, mm (default: from the smallest tool and the stock).
        #[arg(long, value_name = "MM")]
        resolution: Option<f64>,
        /// The cut part: a .png (top view) or .stl (mesh), written whole or not at all.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Write the STL as text instead of binary.
        #[arg(long)]
        ascii: bool,
        /// Picture width in pixels (PNG).
        #[arg(long, default_value_t = 1200)]
        width: u32,
        /// Rapid traverse rate for the time, mm/min (0: leave rapids out).
        #[arg(long = "rapid-rate", value_name = "MM/MIN", default_value_t = 10000.0)]
        rapid_rate: f64,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
        #[command(flatten)]
        run: RunArgs,
    },
    /// Print the values an attribute path reaches in a STEP-NC file, such
    /// as /project/main_workplan/its_elements[*]/its_feature/its_id.
    Query {
        file: PathBuf,
        path: String,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
    },
    /// List the known dialects and their capabilities; with `--spec ID`,
    /// print a built-in spec's XML as built in, to start your own from;
    /// with `--templates ID -o DIR`, copy a dialect's post templates.
    Dialects {
        /// A built-in dialect (id or alias) whose spec to print.
        #[arg(long, conflicts_with = "templates")]
        spec: Option<String>,
        /// A dialect (id or alias, built-in or loaded) whose post templates
        /// to copy into the folder given with -o, to edit and use with
        /// --post-dir. Files already there are kept.
        #[arg(long, value_name = "ID", requires = "output")]
        templates: Option<String>,
        /// With --templates: the folder to write the templates into.
        #[arg(short, long, value_name = "DIR", requires = "templates")]
        output: Option<PathBuf>,
    },
    /// Explain a diagnostic code (`E0201`) or name (`two-motion-codes`);
    /// without one, list them all.
    Explain { code: Option<String> },
}

/// A LinuxCNC configuration (dialects with `var-and-ini-files`; see
/// docs/linuxcnc-config.md).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct ConfigArgs {
    /// A LinuxCNC INI file: its [RS274NGC] settings (SUBROUTINE_PATH,
    /// PARAMETER_FILE, INI_VARS, ORIENT_OFFSET, DISABLE_G92_PERSISTENCE,
    /// DISABLE_FANUC_STYLE_SUB), as `rs274 -i`.
    #[arg(long = "ini", value_name = "FILE.ini")]
    pub ini: Option<PathBuf>,
    /// A LinuxCNC parameter file: read before the run and written back
    /// after it, as `rs274 -v` (instead of the INI's PARAMETER_FILE).
    #[arg(long = "var-file", value_name = "FILE.var")]
    pub var_file: Option<PathBuf>,
}

impl ConfigArgs {
    pub fn files(&self) -> crate::cli::rs274_config::ConfigFiles<'_> {
        crate::cli::rs274_config::ConfigFiles {
            ini: self.ini.as_deref(),
            var_file: self.var_file.as_deref(),
        }
    }
}

/// How a program is run.
#[derive(clap::Args, Debug, Clone)]
pub struct RunArgs {
    /// Most iterations of any one loop before the run stops.
    #[arg(long = "max-loop", default_value_t = 1_000_000)]
    pub max_loop: u64,
    /// Deepest nesting of subprogram and macro calls.
    #[arg(long = "max-depth", default_value_t = 64)]
    pub max_depth: u32,
    /// Units of the tool table and stored positions (LinuxCNC's standalone
    /// interpreter: inch).
    #[arg(long = "machine-units", value_enum, default_value_t = MachineUnits::Inch)]
    pub machine_units: MachineUnits,
    /// Skip blocks that start with `/` (the block-delete switch on).
    #[arg(long = "block-delete")]
    pub block_delete: bool,
    /// The machine: reference point and work offsets (TOML; see
    /// docs/machine.md). `check`, `stats`, `plot`, `diff` and `stepnc`
    /// otherwise assume a reference point 500 mm above work zero.
    #[arg(long = "machine", value_name = "FILE")]
    pub machine: Option<std::path::PathBuf>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MachineUnits {
    Inch,
    Mm,
}

impl RunArgs {
    pub fn options(&self) -> crate::interp::Options {
        let mut o = crate::interp::Options::default();
        o.limits.loop_iterations = self.max_loop;
        o.limits.call_depth = self.max_depth;
        o.machine_units = match self.machine_units {
            MachineUnits::Inch => crate::ir::LengthUnit::Inch,
            MachineUnits::Mm => crate::ir::LengthUnit::Mm,
        };
        o.block_delete = self.block_delete;
        o.machine = self.machine.as_deref().map(load_machine);
        o
    }

    /// [`Self::options`] for the commands that look at where the tool goes
    /// on the machine: without `--machine`, the default machine.
    pub fn analysis_options(&self) -> crate::interp::Options {
        let mut o = self.options();
        o.machine.get_or_insert_with(Default::default);
        o.report_tool_sizes = true;
        o
    }
}

/// Reads `--machine FILE`; a file that cannot be read or is wrong ends the
/// run with exit 2 (a usage error) before anything is written.
fn load_machine(path: &std::path::Path) -> crate::interp::machine_desc::Machine {
    let result = std::fs::read_to_string(path)
        .map_err(|e| e.to_string())
        .and_then(|t| {
            if t.len() > 1 << 20 {
                return Err("a machine description is at most 1 MiB".into());
            }
            crate::interp::machine_desc::Machine::parse(&t)
        });
    result.unwrap_or_else(|e| {
        eprintln!("error: --machine {}: {e}", path.display());
        std::process::exit(2)
    })
}
