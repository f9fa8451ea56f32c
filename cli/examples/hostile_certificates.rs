//! Writes the hostile stroke certificates of `lncert::gen::hostile` to
//! files, for trying `lncert verify` (or another verifier) on them:
//!
//! ```sh
//! cargo run --release --example hostile_certificates -- rectangles 8000 > r.json
//! cargo run --release --example hostile_certificates -- wiggly 200 100 20 > w.json
//! cargo run --release --example hostile_certificates -- far 100000 > f.json
//! lncert verify r.json --json
//! ```
use lncert::gen::hostile;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n = |i: usize, d: usize| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let doc = match args.first().map(String::as_str) {
        Some("rectangles") => hostile::stacked_rectangles(n(1, 8000)),
        Some("wiggly") => hostile::wiggly_witnesses(n(1, 200), n(2, 100), n(3, 20)),
        Some("far") => hostile::far_pieces(n(1, 100_000)),
        _ => {
            eprintln!(
                "usage: hostile_certificates rectangles K | wiggly PARTS COPIES DEGREE | far N"
            );
            std::process::exit(2);
        }
    };
    println!("{doc}");
}
