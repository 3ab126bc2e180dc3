//! `study`: a thin binary over `bonkers::study::cli`.

fn main() {
    let code = bonkers::study::cli::main(std::env::args_os().collect(), &bonkers::simulate::run);
    std::process::exit(code);
}
