//! The `lncert` command line. Everything lives in [`cli`]; this file only
//! parses the arguments and exits with the code the command returns
//! (0 = certified/OK, 1 = refuted/erratum/undecided, 2 = bad input).

mod cli;
mod logger;

use clap::Parser;

fn main() {
    logger::init();
    let args = match cli::Cli::try_parse() {
        Ok(args) => args,
        Err(e) => std::process::exit(cli::usage_error(&e)),
    };
    let code = cli::run(args);
    if let Some(kb) = logger::peak_memory_kb() {
        log::debug!("peak memory: {kb} kB (VmHWM)");
    }
    std::process::exit(code);
}
