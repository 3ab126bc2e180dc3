//! `study`: a thin binary over `bonkers::cli`.

// Large arrays in 2 MiB pages (see `bonkers::pages`).
#[global_allocator]
static ALLOCATOR: bonkers::pages::HugePages = bonkers::pages::HugePages;

fn main() {
    let code = bonkers::cli::main(
        std::env::args_os().collect(),
        &bonkers::runner::execute::simulate::run,
    );
    std::process::exit(code);
}
