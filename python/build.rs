//! Embeds the curated golden cases (`../golden/cases/*.toml`) in the
//! extension, so that an installed package needs no checkout of the
//! repository: `cylroll.golden.case(name)` reads them from here.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let dir = manifest.join("..").join("golden").join("cases");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| {
            panic!(
                "cannot read {}: {e} (build the Python package from a checkout of the repository)",
                dir.display()
            )
        })
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut out = String::from(
        "/// The golden cases: (name, TOML text), sorted by name.\npub const CASES: &[(&str, &str)] = &[\n",
    );
    for p in &paths {
        println!("cargo:rerun-if-changed={}", p.display());
        let name = p
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("UTF-8 case name");
        let abs = p.canonicalize().expect("case path");
        writeln!(
            out,
            "    ({name:?}, include_str!({:?})),",
            abs.display().to_string()
        )
        .expect("write to a String");
    }
    out.push_str("];\n");
    let dest =
        PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("golden_cases.rs");
    std::fs::write(&dest, out).expect("write golden_cases.rs");
}
