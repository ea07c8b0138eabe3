//! The three integrators of the motion with friction on one case:
//! `cargo run --release --example cross_check -- DIGITS MU_FLOOR MU_CONTACT`.
use cylroll::crosscheck::routes;
use cylroll::exact::Exact;
use cylroll::model::{Law, Model};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let digits: u32 = a.get(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let law = |i: usize| Law::parse_mu("mu", a.get(i).map_or("0.3", |s| s.as_str())).expect("mu");
    let m = Model::paper_default(Exact::parse("theta0", "1/10", false).expect("theta0"))
        .with_laws(law(2), law(3))
        .expect("model");
    let t = std::time::Instant::now();
    match routes::cross_check(&m, digits) {
        Ok(rows) => {
            for r in rows {
                println!(
                    "{:16} {:6.1} digits  {}",
                    r.name,
                    r.digits,
                    r.spectral.to_string_radix(10, Some(25))
                );
            }
        }
        Err(e) => println!("error: {e}"),
    }
    println!("{:.2} s", t.elapsed().as_secs_f64());
}
