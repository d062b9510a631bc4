//! The `cncc` binary.

use clap::Parser;

fn main() {
    let cli = cncc::cli::args::Cli::parse();
    std::process::exit(cncc::cli::run(cli));
}
