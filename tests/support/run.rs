//! Running the `cylroll` binary from the repository's root, for tests that
//! read what it prints.

use assert_cmd::Command;

/// What `cylroll args` prints on stdout, asserting that it succeeded (its
/// stderr in the failure's message).
pub fn stdout_ok(args: &[&str]) -> String {
    let out = Command::cargo_bin("cylroll")
        .unwrap()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}
