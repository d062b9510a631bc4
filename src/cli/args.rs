//! The command line, as clap reads it. DESIGN.md's contract: exit 0 on
//! success, 1 when the input has errors, 2 on usage or I/O errors.

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

#[derive(Parser, Debug)]
#[command(name = "cncc", version, about = "A compiler for CNC milling part programs")]
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
    /// List the known dialects and their capabilities.
    Dialects,
    /// Explain a diagnostic code (`E0201`) or name (`two-motion-codes`);
    /// without one, list them all.
    Explain { code: Option<String> },
}
