use cylroll::exact::Exact;
use cylroll::friction::{self, Friction, Law};
use cylroll::model::Model;
fn main() {
    let fr = Friction {
        floor: Law::parse("m", "0.3").unwrap(),
        contact: Law::parse("m", "0.3").unwrap(),
    };
    let m = Model::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
    for p in [124u32, 171] {
        let t = std::time::Instant::now();
        let h = friction::default_horizon(&m, p);
        let mo = friction::solve(&m, &fr, p, &[], true, &h).unwrap();
        println!(
            "{p}: {:.1} ms, {} events, {:?}",
            t.elapsed().as_secs_f64() * 1e3,
            mo.events.len(),
            mo.work_done
        );
    }
}
