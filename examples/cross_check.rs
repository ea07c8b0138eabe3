//! Both integrators of the motion with friction on one case:
//! `cargo run --release --example cross_check -- DIGITS MU_FLOOR MU_CONTACT`.
use cylroll::exact::Exact;
use cylroll::model::Ideal;
use cylroll::motion::{answer, Friction, Law};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let digits: u32 = a.get(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let law = |i: usize| Law::parse("mu", a.get(i).map_or("0.3", |s| s.as_str())).expect("mu");
    let fr = Friction {
        floor: law(2),
        contact: law(3),
    };
    let m = Ideal::paper_default(Exact::parse("theta0", "1/10", false).expect("theta0"));
    let t = std::time::Instant::now();
    match answer::cross_check(&m, &fr, digits) {
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
