//! Placed-and-routed speed of the RTL units (`bash vectors/rtl/pnr.sh`, Yosys `synth_ecp5` and
//! nextpnr-ecp5 for a Lattice LFE5U-85F): the committed `host/report/pnr.json` is well formed and
//! consistent with the RTL and with `host/report/synth.json` (the planar unit's and the bounds
//! unit's builds present, in-context harness counts inside the flip-flops,
//! each unit's parameters those of its RTL and configuration, results per second = Fmax × results
//! per clock, resources within the device, the planar unit's multipliers as synthesized),
//! docs/rtl.md shows its figures, and the script rejects bad input by name. `UVT_EXTENSIVE=1`
//! also places and routes the small pipelined multiplier (`mul31`, 8 s here once the venv
//! exists; needs Debian's yosys, jq and PyPI access for the nextpnr venv, which `tests/run.sh`
//! does not install).

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;
use uvt_tests::extensive;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn load(p: &Path) -> Value {
    let text = std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: not JSON: {e}", p.display()))
}

/// The unit entry named `name` of a pnr.json.
fn unit<'a>(j: &'a Value, name: &str) -> &'a Value {
    j["units"]
        .as_array()
        .expect("a \"units\" array")
        .iter()
        .find(|u| u["unit"] == name)
        .unwrap_or_else(|| panic!("no unit {name} in pnr.json: {j}"))
}

/// The checks every entry of a pnr.json passes: a positive Fmax, results per second = Fmax ×
/// results per clock (rounded), resources used within those available, a named critical path
/// whose delay is 1/Fmax, and positive tool times.
fn check_entry(u: &Value) {
    let name = u["unit"].as_str().expect("unit name");
    let fmax = u["fmax_mhz"]
        .as_f64()
        .unwrap_or_else(|| panic!("{name}: no fmax_mhz"));
    assert!(
        u["target_mhz"].as_f64().is_some_and(|t| t > 0.0),
        "{name}: no target_mhz"
    );
    assert!(fmax > 0.0 && fmax < 1000.0, "{name}: fmax {fmax}");
    let rate = u["results_per_clock"].as_u64().expect("results_per_clock");
    assert!(rate >= 1, "{name}");
    let rps = u["results_per_second"]
        .as_f64()
        .expect("results_per_second");
    assert_eq!(rps, (fmax * 1e6 * rate as f64).round(), "{name}: {u}");
    for (cell, r) in u["resources"].as_object().expect("resources") {
        let (used, avail) = (r["used"].as_u64(), r["available"].as_u64());
        assert!(
            used.zip(avail).is_some_and(|(a, b)| a <= b && b > 0),
            "{name}: {cell} {r}"
        );
    }
    for cell in ["MULT18X18D", "TRELLIS_COMB", "TRELLIS_FF"] {
        assert!(u["resources"][cell]["used"].is_u64(), "{name}: no {cell}");
    }
    // The latency the RTL defines (at least one clock), and results per second per
    // MULT18X18D = results per second ÷ the multipliers used (rounded; null without one).
    assert!(
        u["latency"].as_u64().is_some_and(|l| l >= 1),
        "{name}: latency {}",
        u["latency"]
    );
    let mult = u["resources"]["MULT18X18D"]["used"].as_u64().unwrap_or(0);
    let per = &u["results_per_second_per_mult18x18d"];
    if mult == 0 {
        assert!(per.is_null(), "{name}: {per} per MULT18X18D without one");
    } else {
        assert_eq!(
            per.as_f64(),
            Some((rps / mult as f64).round()),
            "{name}: {u}"
        );
    }
    let cp = &u["critical_path"];
    for k in ["from", "to", "from_net", "to_net"] {
        assert!(
            cp[k].as_str().is_some_and(|s| !s.is_empty()),
            "{name}: critical path {k}: {cp}"
        );
    }
    // The path's delay is the clock period nextpnr reports (both rounded; 2 ps of slack).
    let ns = cp["ns"].as_f64().expect("critical path ns");
    assert!(
        (ns - 1000.0 / fmax).abs() < 0.02,
        "{name}: {ns} ns at {fmax} MHz"
    );
    let parts = cp["logic_ns"].as_f64().unwrap() + cp["routing_ns"].as_f64().unwrap();
    assert!((parts - ns).abs() < 0.005, "{name}: {cp}");
    assert!(
        u["synth_seconds"].as_u64().is_some() && u["pnr_seconds"].as_u64().is_some_and(|s| s > 0)
    );
    // In context, pnr.sh's harness adds one flip-flop per input and output bit of the unit:
    // counted, and inside the flip-flops the report gives.
    let h = &u["harness"];
    if !h.is_null() {
        let (ni, no, ff) = (
            h["input_bits"].as_u64().unwrap_or(0),
            h["output_bits"].as_u64().unwrap_or(0),
            h["TRELLIS_FF"].as_u64().unwrap_or(0),
        );
        assert!(ni > 0 && no > 0 && ff == ni + no, "{name}: harness {h}");
        let used = u["resources"]["TRELLIS_FF"]["used"].as_u64().unwrap();
        assert!(ff < used, "{name}: harness {ff} FF of {used}");
    }
}

/// The committed pnr.json: the planar static unit (`uvt_psample.v`, default and `PIPE = 1`
/// builds) and every bounded unit in it (`uvt_bsample.v`) well formed; each unit's parameters
/// are parameters of its RTL and a bounded unit's match its configuration's name
/// (bounded-POS-TUV-B-OFF); the default planar unit's MULT18X18D count is the synthesized one of
/// synth.json; docs/rtl.md's section shows every unit's Fmax, results per second and multipliers.
#[test]
fn committed_pnr_report_is_consistent() {
    let j = load(&root().join("host/report/pnr.json"));
    assert_eq!(j["script"], "bash vectors/rtl/pnr.sh");
    assert!(
        j["nextpnr"]
            .as_str()
            .is_some_and(|s| s.contains("nextpnr-")),
        "{}",
        j["nextpnr"]
    );
    assert!(
        j["yosys"].as_str().is_some_and(|s| s.starts_with("Yosys")),
        "{}",
        j["yosys"]
    );
    for u in j["units"].as_array().unwrap() {
        check_entry(u);
        let top = u["top"].as_str().unwrap();
        let rtl = std::fs::read_to_string(root().join(format!("vectors/rtl/{top}.v"))).unwrap();
        for p in u["params"].as_object().unwrap().keys() {
            assert!(
                rtl.contains(&format!("parameter {p} ")),
                "{top}.v has no parameter {p}"
            );
        }
        if top == "uvt_bsample" || top == "uvt_bounds" {
            let cfg = u["config"].as_str().unwrap();
            let f: Vec<u64> = cfg
                .strip_prefix("bounded-")
                .unwrap_or_else(|| panic!("{cfg}"))
                .split('-')
                .map(|x| x.parse().unwrap())
                .collect();
            let par = |k: &str| u["params"][k].as_u64();
            let (got, want) = if top == "uvt_bsample" {
                (
                    [par("POS"), par("TUV"), par("OFF")],
                    [Some(f[0]), Some(f[1]), Some(f[3])],
                )
            } else {
                (
                    [par("TUV"), par("BND"), Some(0)],
                    [Some(f[1]), Some(f[2]), Some(0)],
                )
            };
            assert_eq!(got, want, "{}: parameters against {cfg}", u["unit"]);
        }
    }
    let p = unit(&j, "psample");
    assert_eq!(p["top"], "uvt_psample");
    assert_eq!(p["config"], "planar-16-16-16-20");
    assert_eq!(unit(&j, "psample-pipe1")["params"]["PIPE"], 1);
    // The bounds unit, default and PIPE = 1, at the default configuration.
    for name in ["bounds", "bounds-pipe1"] {
        let b = unit(&j, name);
        assert_eq!(b["top"], "uvt_bounds", "{name}");
        assert_eq!(b["result"], "tile", "{name}");
    }
    assert_eq!(unit(&j, "bounds-pipe1")["params"]["PIPE"], 1);
    // A routed bounded sample-test unit at the default configuration: 17-bit LUT chunks (the
    // LUTW = 8 build does not route on the 85F, docs/rtl.md), fewer multipliers than the
    // default tiling's 126.
    let b = unit(&j, "bsample-lut17");
    assert_eq!(b["top"], "uvt_bsample");
    assert_eq!(b["config"], uvt_host::config::names::DEFAULT_NAME);
    assert_eq!(b["params"]["LUTW"], 17);
    let mult = b["resources"]["MULT18X18D"]["used"].as_u64().unwrap();
    assert!(mult < 126, "bsample-lut17: {mult} MULT18X18D");
    let synth = load(&root().join("host/report/synth.json"));
    let sp = synth["units"]
        .as_array()
        .unwrap()
        .iter()
        .find(|u| u["name"] == "planar-16-16-16-20")
        .expect("planar unit in synth.json");
    assert_eq!(
        p["resources"]["MULT18X18D"]["used"], sp["ecp5"]["mult18x18d"],
        "the planar unit's multipliers: pnr.json against synth.json"
    );
    let docs = std::fs::read_to_string(root().join("docs/rtl.md")).unwrap();
    let sec = docs
        .split("## Placed and routed speed")
        .nth(1)
        .expect("docs/rtl.md: a section \"Placed and routed speed\"");
    for u in j["units"].as_array().unwrap() {
        let fmax = format!("{:.1} MHz", u["fmax_mhz"].as_f64().unwrap());
        let rps = format!("{:.1} M/s", u["results_per_second"].as_f64().unwrap() / 1e6);
        let mult = format!("{} MULT18X18D", u["resources"]["MULT18X18D"]["used"]);
        for want in [&fmax, &rps, &mult] {
            assert!(
                sec.contains(want.as_str()),
                "docs/rtl.md lacks {want} of {}",
                u["unit"]
            );
        }
    }
}

/// A pnr.json with a results-per-second figure that is not Fmax × rate, or a per-multiplier
/// figure that is not results per second ÷ MULT18X18D, fails the check.
#[test]
fn a_wrong_rate_in_pnr_json_is_caught() {
    let j = load(&root().join("host/report/pnr.json"));
    for key in ["results_per_second", "results_per_second_per_mult18x18d"] {
        let mut bad = j["units"][0].clone();
        let v = bad[key].as_f64().unwrap();
        bad[key] = serde_json::json!(v + 1000.0);
        let r = std::panic::catch_unwind(|| check_entry(&bad));
        assert!(r.is_err(), "a changed {key} passed");
    }
}

/// Bad input to pnr.sh: an unknown unit, a bad seed, an unknown option: a message naming it and
/// a non-zero exit, before any tool runs.
#[test]
fn pnr_script_rejects_bad_input_by_name() {
    for (args, want) in [
        (&["nosuch"][..], "unknown unit 'nosuch'"),
        (&["-s", "x1", "psample"][..], "-s 'x1' is not"),
        (&["-f", "fast", "psample"][..], "-f 'fast' is not"),
        (&["--bogus"][..], "unknown option --bogus"),
        (&["-a"][..], "-a needs a value"),
    ] {
        let out = Command::new("bash")
            .arg(root().join("vectors/rtl/pnr.sh"))
            .args(args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

/// `UVT_EXTENSIVE=1`: pnr.sh places and routes the pipelined 31 × 31 multiplier (`uvt_mul.v`,
/// 18 × 18 tiling; REG = 2, and REG = 3 on MULT18X18D primitives) and writes well-formed entries
/// with the 4 MULT18X18D of its tiling and the latency of each form.
#[test]
fn pnr_script_places_and_routes_a_small_unit() {
    if !extensive() {
        eprintln!("skipped: set UVT_EXTENSIVE=1 (needs yosys, jq and the nextpnr venv)");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out_json = dir.path().join("pnr.json");
    let out = Command::new("bash")
        .arg(root().join("vectors/rtl/pnr.sh"))
        .arg("-o")
        .arg(&out_json)
        .args(["mul31", "mul31-pipe2"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let j = load(&out_json);
    let u = unit(&j, "mul31");
    check_entry(u);
    assert_eq!(u["resources"]["MULT18X18D"]["used"], 4, "{u}");
    assert_eq!(u["latency"], 2, "{u}");
    // REG = 3 on MULT18X18D primitives (MAP = 1): the same 4 multipliers, 5 clocks.
    let u = unit(&j, "mul31-pipe2");
    check_entry(u);
    assert_eq!(u["resources"]["MULT18X18D"]["used"], 4, "{u}");
    assert_eq!(u["latency"], 5, "{u}");
}

/// `uvt precision` reads pnr.json from synth.json's folder: the table of the placed-and-routed
/// units and, in the cost cell of each unit's configuration, its Fmax and results per second.
#[test]
fn precision_report_shows_the_pnr_figures() {
    use uvt_host::precision::costs::Costs;
    let j = load(&root().join("host/report/pnr.json"));
    let c = Costs::load(
        &root().join("host/report/no-such-m4.json"),
        &root().join("host/report/synth.json"),
    )
    .unwrap();
    let md = c.pnr_md();
    for u in j["units"].as_array().unwrap() {
        let name = u["unit"].as_str().unwrap();
        let fmax = u["fmax_mhz"].as_f64().unwrap();
        assert!(
            md.contains(&format!("| {name} | `{}` |", u["top"].as_str().unwrap())),
            "{md}"
        );
        let cell = c.of(u["config"].as_str().unwrap()).synth;
        assert!(
            cell.contains(&format!("ECP5 P&R {name}: {fmax:.1} MHz")),
            "{name}: {cell}"
        );
    }
}
