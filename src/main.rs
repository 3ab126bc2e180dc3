//! `study`: a thin binary over `bonkers::cli`.

fn main() {
    let code = bonkers::cli::main(
        std::env::args_os().collect(),
        &bonkers::runner::simulate::run,
    );
    std::process::exit(code);
}
