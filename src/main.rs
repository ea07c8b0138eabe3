//! The `cylroll` command: see `cylroll --help` and the README.

mod cli;

fn main() {
    std::process::exit(cli::main_with(std::env::args().collect()));
}
