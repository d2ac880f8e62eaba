//! `uvt`: command-line tools of the uvt reference model. Bad input exits non-zero with a message
//! naming what is wrong.
#![forbid(unsafe_code)]
// Lines on stderr go through `log::line`: a closed pipe must not panic.
#![deny(clippy::print_stderr)]

use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

use anyhow::{anyhow, bail, Context, Result};
use clap::Parser;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::Laine2011;
use uvt_host::config::names;
use uvt_host::scene::budget;
use uvt_host::scene::builtin::{self, Bench, Blur};
use uvt_host::scene::file::{LoadOpts, Scene};

mod cli;
use cli::{Cli, Cmd, FrameArgs, SceneCmd, VecCmd};

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        // A closed stdout (`uvt vectors layout | head`) ends the program quietly.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            uvt_host::log::line(&format!("uvt: error: {e:#}"));
            ExitCode::FAILURE
        }
    }
}

fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// Write to stdout; a closed pipe comes back as an error that `main` treats as a quiet exit.
fn say(text: &str) -> Result<()> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// `WxH` → (W, H).
fn parse_viewport(s: &str) -> Result<(u16, u16)> {
    let bad = || anyhow!("--viewport {s:?}: expected WxH with W, H in 1..=2048, e.g. 320x180");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let d = |x: &str| {
        x.trim()
            .parse::<u16>()
            .ok()
            .filter(|v| (1..=2048).contains(v))
    };
    Ok((d(w).ok_or_else(bad)?, d(h).ok_or_else(bad)?))
}

impl FrameArgs {
    /// The strategy `--bounds` names.
    fn strategy(&self) -> Result<&'static str> {
        names::strategy("--bounds", &self.bounds)
    }

    /// The first of these options given, if any (`--bounds` counts when not its default).
    fn given(&self) -> Option<&'static str> {
        [
            (self.spp.is_some(), "--spp"),
            (self.tile.is_some(), "--tile"),
            (self.viewport.is_some(), "--viewport"),
            (self.bounds != Laine2011.name(), "--bounds"),
        ]
        .into_iter()
        .find_map(|(given, opt)| given.then_some(opt))
    }

    /// The scene file at `path` (its warnings on stderr), or without one the built-in default
    /// scene, under these options and the memory budget `mem_budget` (bytes).
    fn scene(&self, path: Option<&Path>, mem_budget: u64) -> Result<Scene> {
        if let Some(t) = self.tile.filter(|t| ![1, 2, 4, 8].contains(t)) {
            bail!("--tile {t}: not one of 1, 2, 4, 8");
        }
        let load = LoadOpts {
            mem_budget,
            viewport: self.viewport.as_deref().map(parse_viewport).transpose()?,
            spp: self.spp,
        };
        let mut s = match path {
            Some(p) => {
                let l = Scene::load_with(p, &load)?;
                for w in &l.warnings {
                    uvt_host::log::line(&format!("uvt: warning: {}: {w}", p.display()));
                }
                l.scene
            }
            None => builtin::default_scene().with_opts(&load)?,
        };
        s.tile = self.tile.unwrap_or(s.tile);
        Ok(s)
    }
}

/// Built-in scenes by name: `default` and the benchmark rows `game-motion`, `dense-both2`, …
/// (`-quick` for the quarter size; `default` has no quick form: it is the small scene).
fn builtin(name: &str) -> Result<Scene> {
    let names = builtin_names();
    if name == "default" {
        return Ok(builtin::default_scene());
    }
    let (base, quick) = match name.strip_suffix("-quick") {
        Some(b) => (b, true),
        None => (name, false),
    };
    for kind in Bench::NAMED {
        for row in Blur::ALL {
            if bench_name(kind, row) == base {
                let mut s = builtin::bench_scene(kind, row, quick);
                s.name = name.to_string();
                return Ok(s);
            }
        }
    }
    let hint =
        uvt_host::scene::json::nearest(name, &names.iter().map(String::as_str).collect::<Vec<_>>())
            .map_or(String::new(), |n| format!("did you mean {n:?}? "));
    bail!("unknown built-in scene {name:?}; {hint}(see `uvt scene list`)")
}

fn bench_name(kind: Bench, row: Blur) -> String {
    format!("{}-{}", kind.name(), row.label().replace(" x", ""))
}

/// Every name [`builtin`] accepts: `default`, then each benchmark row and its `-quick` form.
fn builtin_names() -> Vec<String> {
    let mut v = vec!["default".to_string()];
    for kind in Bench::NAMED {
        for row in Blur::ALL {
            v.push(bench_name(kind, row));
            v.push(bench_name(kind, row) + "-quick");
        }
    }
    v
}

fn run(cli: Cli) -> Result<()> {
    match cli.cmd {
        Cmd::Render {
            scene,
            out,
            frame,
            seed,
            precision,
            mem_budget,
        } => {
            uvt_host::render::scene_render::check_out_dir(&out)?;
            let opts = uvt_host::render::opts::RenderOpts {
                bounds: frame.strategy()?,
                precision: names::precision("--precision", &precision)?,
                progress: true,
            };
            let budget = budget::parse_size(&mem_budget).context("--mem-budget")?;
            let mut s = frame.scene(scene.as_deref(), budget)?;
            s.seed = seed.unwrap_or(s.seed);
            let r = uvt_host::render::scene_render::render_with(&s, &opts)?;
            let files = uvt_host::render::scene_render::write(&r, &s, &out)?;
            say(&uvt_host::render::report::report_md(&r))?;
            for f in files {
                say(&format!("wrote {}\n", f.display()))?;
            }
        }
        Cmd::Scene(SceneCmd::List) => {
            say(&(builtin_names().join("\n") + "\n"))?;
        }
        Cmd::Scene(SceneCmd::Export { name, out }) => {
            let s = builtin(&name)?;
            let text = serde_json::to_string(&s.to_json())? + "\n";
            match out {
                None => say(&text)?,
                Some(p) => write_atomic(&p, text.as_bytes())?,
            }
        }
        Cmd::BenchSte {
            quick,
            json,
            scene,
            row,
            tile_sweep,
            no_limit,
            limit_effort,
            precision,
        } => {
            let cfg = names::precision("--precision", &precision)?;
            let effort = match limit_effort.as_deref() {
                None => uvt_host::bench::ste_table::ORACLE_EFFORT,
                Some(e) => uvt_host::bench::ste_table::parse_effort(e)
                    .map_err(|m| anyhow!("--limit-effort {e:?}: {m}"))?,
            };
            let kinds: Vec<Bench> = match scene.as_deref() {
                None => Bench::ALL.to_vec(),
                Some(n) => vec![Bench::from_name(n).map_err(|e| anyhow!("--scene: {e}"))?],
            };
            let rows_sel: Vec<Blur> = match row.as_deref() {
                None => Blur::ALL.to_vec(),
                Some(r) => vec![Blur::from_name(r).map_err(|e| anyhow!("--row: {e}"))?],
            };
            let rows = uvt_host::bench::ste_table::run_table_of(
                cfg,
                quick,
                uvt_host::bench::ste_table::timing(quick),
                &kinds,
                &rows_sel,
                tile_sweep,
                (!no_limit).then_some(effort),
            )?;
            say(&uvt_host::bench::ste_table::table_md(&rows))?;
            if let Some(p) = json {
                write_atomic(&p, (serde_json::to_string_pretty(&rows)? + "\n").as_bytes())?;
            }
        }
        Cmd::BenchZmax { quick, json } => {
            let rows = uvt_host::bench::zmax::run_rows::<uvt_core::DefaultPrecision>(quick)?;
            say(&uvt_host::bench::zmax::table_md(&rows))?;
            if let Some(p) = json {
                write_atomic(&p, (serde_json::to_string_pretty(&rows)? + "\n").as_bytes())?;
            }
        }
        Cmd::M4Workload {
            scene,
            row,
            quick,
            every,
            out,
        } => {
            let kind = Bench::from_name(&scene).map_err(|e| anyhow!("--scene: {e}"))?;
            let row = Blur::from_name(&row).map_err(|e| anyhow!("--row: {e}"))?;
            let bytes = uvt_host::bench::workload::bench_workload(kind, row, quick, every)?;
            write_atomic(&out, &bytes)?;
            say(&format!(
                "wrote {} ({} bytes)\n",
                out.display(),
                bytes.len()
            ))?;
        }
        Cmd::AutoRule { m4, out } => {
            let stages = uvt_host::bench::m4_stages::M4Stages::load(&m4)?;
            let rules = uvt_host::bench::auto_rule::derive(&stages)?;
            let src = uvt_host::bench::auto_rule::rule_source(&rules, &m4.display().to_string());
            write_atomic(&out, src.as_bytes())?;
            say(&src)?;
        }
        Cmd::Converge {
            scene,
            out,
            repeats,
        } => {
            let s = match scene {
                Some(p) => Scene::load(&p)?,
                None => builtin::default_scene(),
            };
            let pts = uvt_host::converge::sweep(&s, repeats)?;
            say(&uvt_host::converge::table_md(&pts))?;
            for f in uvt_host::converge::write(&pts, &s, &out)? {
                say(&format!("wrote {}\n", f.display()))?;
            }
        }
        Cmd::Precision {
            quick,
            out,
            replot,
            shrink,
            m4,
            synth,
            configs,
        } => {
            if shrink == Some(0) {
                bail!("--shrink must be at least 1");
            }
            let chosen: Vec<&'static str> = match configs {
                None => uvt_host::precision::row::CONFIGS.to_vec(),
                Some(list) => list
                    .split(',')
                    .map(|n| {
                        let cfg = names::precision("--configs", n.trim())?;
                        uvt_core::config::registry::name_of(cfg)
                            .ok_or_else(|| anyhow!("--configs: {cfg} is not in the registry"))
                    })
                    .collect::<Result<_>>()?,
            };
            let sw = if quick {
                uvt_host::precision::sweep::Sweep {
                    configs: chosen.clone(),
                    scenes: vec![Bench::Game, Bench::Dense],
                    rows: vec![Blur::Static, Blur::Both],
                    tiles: vec![1, 4],
                    shrink: shrink.unwrap_or(2),
                }
            } else {
                uvt_host::precision::sweep::Sweep {
                    configs: chosen.clone(),
                    scenes: vec![Bench::Game, Bench::Dense],
                    rows: Blur::ALL.to_vec(),
                    tiles: vec![1, 2, 4, 8],
                    shrink: shrink.unwrap_or(1),
                }
            };
            let costs = uvt_host::precision::costs::Costs::load(&m4, &synth)?;
            uvt_host::render::scene_render::check_out_dir(&out)?;
            let rows: Vec<uvt_host::precision::row::PrecRow> = match replot {
                Some(p) => serde_json::from_str(
                    &std::fs::read_to_string(&p)
                        .with_context(|| format!("cannot read {}", p.display()))?,
                )
                .map_err(|e| anyhow!("{}: not a precision.json: {e}", p.display()))?,
                None => uvt_host::precision::sweep::sweep(&sw)?,
            };
            let md = uvt_host::precision::tables::table_md(&rows, &costs);
            std::fs::create_dir_all(&out)
                .with_context(|| format!("cannot create {}", out.display()))?;
            write_atomic(&out.join("precision.md"), md.as_bytes())?;
            write_atomic(
                &out.join("precision.json"),
                (serde_json::to_string_pretty(&rows)? + "\n").as_bytes(),
            )?;
            uvt_host::precision::costs::plot_svg(&rows, &costs, &out.join("precision.svg"))
                .with_context(|| format!("writing {}", out.join("precision.svg").display()))?;
            say(&md)?;
        }
        Cmd::Widths { config } => {
            let mut md = String::new();
            match config {
                Some(name) => {
                    let cfg = names::model_config(&name)?;
                    uvt_core::widths::markdown::write_markdown(&mut md, &cfg)?;
                }
                None => uvt_core::widths::markdown::write_readme(&mut md)?,
            }
            say(&md)?;
        }
        Cmd::Cost {
            config,
            strategies: true,
        } => {
            let cfg = match config {
                Some(name) => names::model_config(&name)?,
                None => uvt_core::config::registry::Config::of::<uvt_core::DefaultPrecision>(),
            };
            say(&uvt_host::config::strategy_cost::strategies_md(&cfg))?;
        }
        Cmd::Cost { config, .. } => match config {
            Some(name) => {
                let cfg = names::model_config(&name)?;
                say(&uvt_host::config::multipliers::cost_md(&cfg))?;
            }
            None => say(&uvt_host::config::multipliers::summary_md())?,
        },
        Cmd::Fit {
            scene,
            tolerance,
            clip_tolerance,
            out,
            m4_units,
            m4_units_planar,
            mem_budget,
        } => {
            let tol = tolerance
                .as_deref()
                .map(uvt_host::fit::select::parse_tolerance)
                .transpose()?;
            let clip_tol = clip_tolerance
                .as_deref()
                .map(uvt_host::fit::select::parse_clip_tolerance)
                .transpose()?;
            uvt_host::render::scene_render::check_out_dir(&out)?;
            let m4 = uvt_host::fit::m4::load_m4_units(&m4_units)?;
            let m4_planar = uvt_host::fit::m4::load_m4_units(&m4_units_planar)?;
            let load = LoadOpts {
                mem_budget: budget::parse_size(&mem_budget).context("--mem-budget")?,
                ..LoadOpts::default()
            };
            let l = Scene::load_with(&scene, &load)?;
            for w in &l.warnings {
                uvt_host::log::line(&format!("uvt: warning: {}: {w}", scene.display()));
            }
            let f = uvt_host::fit::report::fit(
                &l.scene,
                tol,
                clip_tol,
                m4,
                &m4_units,
                m4_planar,
                &m4_units_planar,
            )
            .with_context(|| format!("uvt fit {}", scene.display()))?;
            let md = uvt_host::fit::report::fit_md(&f);
            std::fs::create_dir_all(&out)
                .with_context(|| format!("cannot create {}", out.display()))?;
            write_atomic(&out.join("fit.md"), md.as_bytes())?;
            write_atomic(
                &out.join("fit.json"),
                (serde_json::to_string_pretty(&f)? + "\n").as_bytes(),
            )?;
            say(&md)?;
            if !f.ok {
                bail!(
                    "{}: the confirmation failed (see {})",
                    scene.display(),
                    out.join("fit.md").display()
                );
            }
        }
        Cmd::M4Units { file } => say(&uvt_host::fit::m4::programs_md(&file)?)?,
        Cmd::Units {
            config,
            m4_units,
            synth,
        } => {
            let cfg = names::model_config(&config)?;
            let m4 = uvt_host::fit::m4::load_m4_units(&m4_units)?;
            let syn = uvt_host::fit::synth::load_units(&synth)?;
            say(&uvt_host::fit::units_table::units_md(
                &cfg,
                m4.as_ref().map(|m| m.0.as_slice()),
                &m4_units,
                syn.as_deref(),
                &synth,
            ))?;
            say(&uvt_host::fit::synth::planar_md(syn.as_deref(), &synth))?;
            say(&uvt_host::fit::synth::bounds_md(syn.as_deref(), &synth))?;
        }
        Cmd::Splice {
            check,
            block,
            file,
            root,
        } => match (block, file) {
            (Some(name), Some(page)) => {
                let mut body = String::new();
                std::io::Read::read_to_string(&mut std::io::stdin(), &mut body)
                    .context("reading the block from the standard input")?;
                let changed = uvt_host::splice::splice_block(&page, &name, &body)?;
                say(&format!(
                    "{}: block {name} {}\n",
                    page.display(),
                    if changed { "updated" } else { "unchanged" }
                ))?;
            }
            _ => {
                let done = uvt_host::splice::splice_reports(&root, check)?;
                if done.is_empty() {
                    bail!(
                        "no report block in README.md or docs/*.md under {}",
                        root.display()
                    );
                }
                let mut differ = 0;
                for s in &done {
                    differ += usize::from(s.changed);
                    let state = match (s.changed, check) {
                        (false, _) => "same",
                        (true, true) => "differs",
                        (true, false) => "updated",
                    };
                    say(&format!("{}: {} {state}\n", s.at, s.source))?;
                }
                if check && differ > 0 {
                    bail!(
                        "{differ} of {} report blocks differ from their reports",
                        done.len()
                    );
                }
            }
        },
        Cmd::Stress { dir } => {
            let scenes = uvt_host::precision::sweep::stress_scenes(&dir)?;
            let rows: Vec<_> = scenes
                .iter()
                .map(|s| {
                    let row = uvt_host::precision::sweep::stress_row(s)?;
                    Ok((s.name.clone(), s.tris.len(), row))
                })
                .collect::<Result<_>>()?;
            say(&uvt_host::precision::tables::stress_md(&rows))?;
            let bad: Vec<_> = rows
                .iter()
                .filter(|r| r.2.violations > 0 || r.2.beyond_bound > 0 || r.2.lost > 0)
                .map(|r| r.0.clone())
                .collect();
            if !bad.is_empty() {
                bail!(
                    "conservativeness, error-bound or lost-sample failures in: {}",
                    bad.join(", ")
                );
            }
        }
        Cmd::Vectors(VecCmd::Export {
            scene,
            frame,
            config,
            out,
            seed,
        }) => {
            uvt_host::render::scene_render::check_out_dir(&out)?;
            let cfg = config
                .map(|c| names::precision("--config", &c))
                .transpose()?;
            let strategy = frame.strategy()?;
            match scene {
                Some(p) => {
                    let s = frame.scene(Some(&p), budget::DEFAULT_MEM_BUDGET)?;
                    uvt_host::vectors::committed::export_scene(
                        &p,
                        &s,
                        &out,
                        cfg.unwrap_or(uvt_core::config::registry::DEFAULT),
                        strategy,
                    )?
                }
                None => {
                    if let Some(opt) = frame.given() {
                        bail!("{opt} applies to a frame set of one scene: it needs --scene FILE");
                    }
                    uvt_host::vectors::committed::export_default(&out, seed, cfg)?
                }
            }
            say(&format!("wrote vectors to {}\n", out.display()))?;
        }
        Cmd::Vectors(VecCmd::Check { dir }) => {
            let c = uvt_host::vectors::check::check(&dir)?;
            for s in &c.sets {
                say(&format!("ok {}\n", s.display()))?;
            }
            say(&format!(
                "{} records match the core bit for bit\n",
                c.records
            ))?;
        }
        Cmd::Configs { sweep, strategies } => {
            let text = if strategies {
                uvt_core::bounds::registry::STRATEGIES
                    .map(|n| n.to_string() + "\n")
                    .concat()
            } else if sweep {
                uvt_core::config::registry::sweep()
                    .map(|e| e.name.to_string() + "\n")
                    .collect()
            } else {
                names::configs_text()
            };
            say(&text)?;
        }
        Cmd::Vectors(VecCmd::Gen {
            kind,
            config,
            seed,
            count,
            shard,
            spp,
            coverage,
            target_bins,
        }) => {
            use uvt_records::{kind::Kind, stream};
            let k = Kind::parse(&kind).map_err(|e| anyhow!(e))?;
            let s = stream::Stream::new(k, config.as_deref(), seed, spp)
                .and_then(|s| s.targeting(&target_bins))
                .map_err(|e| anyhow!(e))?;
            let shard = stream::Shard::parse(&shard).map_err(|e| anyhow!(e))?;
            let mut cov = uvt_core::coverage::Counts::default();
            let want = coverage.is_some().then_some(&mut cov);
            uvt_host::vectors::pipe::gen(&mut std::io::stdout().lock(), &s, count, shard, want)?;
            if let Some(path) = coverage {
                std::fs::write(&path, uvt_records::coverage::json(k, &cov) + "\n")?;
            }
        }
        Cmd::Vectors(VecCmd::Ver {
            kind,
            arch_only,
            count,
            spp,
            coverage,
        }) => {
            let k = uvt_records::kind::Kind::parse(&kind).map_err(|e| anyhow!(e))?;
            let mut cov = uvt_core::coverage::Counts::default();
            let want = coverage.is_some().then_some(&mut cov);
            let v = uvt_host::vectors::pipe::ver(std::io::stdin().lock(), k, spp, arch_only, want)?;
            if let Some(path) = &coverage {
                std::fs::write(path, uvt_records::coverage::json(k, &cov) + "\n")?;
            }
            for m in &v.msgs {
                say(&format!("MISMATCH {m}\n"))?;
            }
            if v.mismatches > 0 {
                bail!(
                    "{} of {} {kind} pairs differ from the model",
                    v.mismatches,
                    v.pairs
                );
            }
            uvt_host::vectors::pipe::check_count(v.pairs, count, &kind)?;
            say(&format!("PASS {} {kind} pairs match the model\n", v.pairs))?;
        }
        Cmd::Vectors(VecCmd::Coverage {
            vectors,
            count,
            seed,
            json,
        }) => {
            let r = uvt_host::vectors::coverage::report(&vectors, count, seed)?;
            say(&r.text)?;
            if let Some(path) = json {
                std::fs::write(&path, r.json)?;
            }
        }
        Cmd::Vectors(VecCmd::Decode { kind, words }) => {
            let d = uvt_host::vectors::pipe::decode(&kind, &words)?;
            say(&d.text)?;
            if d.differs {
                bail!("the given {kind} output differs from the model's");
            }
        }
        Cmd::Vectors(VecCmd::Layout) => {
            for st in uvt_host::vectors::format::STAGES {
                for io in ["in", "out"] {
                    let spp = if st == "resolve" { 4 } else { 0 };
                    say(
                        &(uvt_host::vectors::format::layout_md(&format!("{st}_{io}"), spp) + "\n"),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// Write a file through a temporary name in the same folder, so a failure leaves nothing
/// half-written; errors name the path.
fn write_atomic(path: &std::path::Path, bytes: &[u8]) -> Result<()> {
    let name = path
        .file_name()
        .ok_or_else(|| anyhow!("{}: not a file name", path.display()))?;
    let tmp = path.with_file_name(format!(".{}.tmp", name.to_string_lossy()));
    std::fs::write(&tmp, bytes).with_context(|| format!("cannot write {}", path.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        anyhow!("cannot write {}: {e}", path.display())
    })
}
