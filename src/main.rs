//! The `cncc` binary.

use clap::Parser;

fn main() {
    cncc::cli::memory::settle_allocator();
    cncc::cli::atomic::install_signal_handlers();
    let cli = cncc::cli::args::Cli::parse();
    std::process::exit(cncc::cli::run(cli));
}
