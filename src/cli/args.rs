//! The command line, as clap reads it. DESIGN.md's contract: exit 0 on
//! success, 1 when the input has errors, 2 on usage or I/O errors.

use clap::{Parser, Subcommand, ValueEnum};
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
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
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
        run: RunArgs,
    },
    /// Re-write a STEP-NC (ISO 14649 Part 21) file normalised; a program
    /// would be raised into STEP-NC.
    Stepnc {
        file: PathBuf,
        /// Write here (whole or not at all) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Raise a program as explicit toolpaths (CC1).
        #[arg(long, conflicts_with = "cc2")]
        cc1: bool,
        /// Raise a program as features and operations (CC2).
        #[arg(long)]
        cc2: bool,
        /// The stock (workpiece block) for raising a program.
        #[arg(long)]
        stock: Option<String>,
        /// The program's dialect when raising; detected when absent.
        #[arg(long)]
        dialect: Option<String>,
        /// A tool table in LinuxCNC's .tbl format, for raising.
        #[arg(long = "tool-table", value_name = "T.tbl")]
        tool_table: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
    },
    /// Print the values an attribute path reaches in a STEP-NC file, such
    /// as /project/main_workplan/its_elements[*]/its_feature/its_id.
    Query {
        file: PathBuf,
        path: String,
        #[arg(long, value_enum, default_value_t = Format::Human)]
        format: Format,
    },
    /// List the known dialects and their capabilities.
    Dialects,
    /// Explain a diagnostic code (`E0201`) or name (`two-motion-codes`);
    /// without one, list them all.
    Explain { code: Option<String> },
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
        o
    }
}
