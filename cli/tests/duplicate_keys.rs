//! A key given twice in a pose object or a spec is refused (exit 2, one `error:` line naming
//! the key), never silently last-wins (issue 30, item 4): in `gam pose`, in every spec of
//! `gam interpolate`, `trajectory`, `sample`, `plot` and `gam hermite`.

use crate::common;

use common::{CONTRACT_EXAMPLE, TempFile, fails};

#[test]
fn a_repeated_key_in_a_pose_object_is_refused() {
    for (arg, key) in [
        (r#"{"axis": [0, 0, 1], "angle": 1, "angle": 2}"#, "angle"),
        (r#"{"position": [0, 0, 0], "position": [1, 0, 0]}"#, "position"),
        (r#"{"hexanion": {"omega": [0, 0, 1], "m": [0, 0, 0], "omega": [1, 0, 0]}}"#, "omega"),
        (r#"{"motor": {"1": 1, "e12": 0.5, "e12": 0}}"#, "e12"),
    ] {
        let e = fails(&["pose", "--json", arg], 2);
        assert!(e.contains(&format!("duplicate key `{key}`")), "{arg}: {e}");
    }
}

#[test]
fn a_repeated_key_in_a_spec_is_refused() {
    let two = r#"{"position": [0, 0, 0]}, {"position": [1, 0, 0]}"#;
    for (name, text, key) in [
        (
            "pose",
            format!(
                r#"{{"method": "ccm-additive", "poses": [{two}, {{"position": [2, 0, 0], "position": [3, 0, 0]}}]}}"#
            ),
            "key `position`",
        ),
        ("top", format!(r#"{{"method": "ccm-additive", "poses": [{two}], "samples": 3, "samples": 5}}"#), "`samples`"),
        (
            "nested",
            format!(r#"{{"method": "ccm-additive", "poses": [{two}], "parameters": [0, 1], "shape": 1, "shape": 2}}"#),
            "`shape`",
        ),
    ] {
        let spec = TempFile::new(&format!("dup-{name}.json"), &text);
        let e = fails(&["interpolate", "--json", spec.path()], 2);
        assert!(e.contains("duplicate") && e.contains(key), "{name}: {e}");
        for args in [
            vec!["trajectory", spec.path(), "--point", "0,0,0"],
            vec!["sample", spec.path(), "--samples", "3"],
            vec!["plot", spec.path(), "--out", "/nonexistent-dir/x.svg"],
        ] {
            let e = fails(&args, 2);
            assert!(e.contains("duplicate") && e.contains(key), "{args:?}: {e}");
        }
    }
    let hermite =
        TempFile::new("dup-hermite.json", &CONTRACT_EXAMPLE.replace("\"degree\": 3,", "\"degree\": 3, \"degree\": 4,"));
    let e = fails(&["hermite", hermite.path()], 2);
    assert!(e.contains("duplicate field `degree`"), "{e}");
    let control = r#"{"segments": [{"t0": 0, "t1": 1, "t1": 2, "representation": "additive-bezier", "control_poses": [{"1": 1}, {"1": 1}]}]}"#;
    let control = TempFile::new("dup-control.json", control);
    let e = fails(&["plot", control.path(), "--out", "/nonexistent-dir/x.svg"], 2);
    assert!(e.contains("duplicate key `t1`"), "{e}");
}
