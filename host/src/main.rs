//! `uvt`: command-line tools of the uvt reference model. Bad input exits non-zero with a message
//! naming what is wrong.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand};
use uvt_host::{bench, render, scene::Scene, scenes};

#[derive(Parser)]
#[command(
    name = "uvt",
    version,
    about = "uvt: bit-accurate stochastic rasterizer reference model, host tools"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Render a scene (default: the built-in scene) with the core and the f64 reference.
    Render {
        /// scene file (JSON); omitted: the built-in default scene with motion and defocus
        scene: Option<PathBuf>,
        /// output directory
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// STE table analogous to Laine 2011 Table 1 (game and dense scenes, seven rows each).
    BenchSte {
        /// quarter resolution and tessellation (for tests)
        #[arg(long)]
        quick: bool,
        /// also write the rows as JSON here
        #[arg(long)]
        json: Option<PathBuf>,
        /// only this scene (game or dense)
        #[arg(long)]
        scene: Option<String>,
        /// only this row (static, motion, motion2, defocus, defocus2, both, both2)
        #[arg(long)]
        row: Option<String>,
        /// add the table over bounds-tile sizes 1, 2, 4, 8 (four times the strategy runs)
        #[arg(long)]
        tile_sweep: bool,
        /// skip the axis-aligned limit (its dense sampling takes most of the run)
        #[arg(long)]
        no_limit: bool,
    },
    /// Image error against run time: every bounds strategy at 1..64 spp against a 256-spp f64
    /// reference; writes converge.md, converge.json, converge.svg.
    Converge {
        /// scene file (JSON); omitted: the built-in default scene
        scene: Option<PathBuf>,
        /// output directory
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// frames per point (the median wall time is kept)
        #[arg(long, default_value_t = 3)]
        repeats: usize,
    },
    /// Sweep precisions against the f64 reference (error, run time, epsilon).
    Precision {
        /// small sizes and fewer rows (for tests)
        #[arg(long)]
        quick: bool,
        /// output directory for precision.md, precision.json, precision.svg
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// do not sweep: redraw the table and plot from a precision.json
        #[arg(long)]
        replot: Option<PathBuf>,
    },
    /// Stiff and extreme cases: STE, error against f64 and conservativeness per scene file.
    Stress {
        /// folder of scene files
        #[arg(default_value = "host/stress")]
        dir: PathBuf,
    },
    /// Golden test vectors for RTL.
    #[command(subcommand)]
    Vectors(VecCmd),
}

#[derive(Subcommand)]
enum VecCmd {
    /// Write vectors: without --scene the committed set (unit/, frame_a/, frame_b/) into DIR.
    Export {
        /// frame-level vectors of this scene file only
        #[arg(long)]
        scene: Option<PathBuf>,
        /// output directory
        #[arg(long)]
        out: PathBuf,
        /// seed of the unit-level random inputs
        #[arg(long, default_value_t = uvt_host::vectors::DEFAULT_SEED)]
        seed: u64,
    },
    /// Re-run the core on the vectors in DIR and compare bit for bit.
    Check {
        /// a vector set, or a folder of sets
        dir: PathBuf,
    },
    /// Print the bit-layout tables of every file (Markdown).
    Layout,
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("uvt: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<()> {
    match cli.cmd {
        Cmd::Render { scene, out } => {
            let s = match scene {
                Some(p) => Scene::load(&p)?,
                None => scenes::default_scene(),
            };
            let r = render::render(&s)?;
            let files = render::write(&r, &s, &out)?;
            print!("{}", render::report_md(&r));
            for f in files {
                println!("wrote {}", f.display());
            }
        }
        Cmd::BenchSte {
            quick,
            json,
            scene,
            row,
            tile_sweep,
            no_limit,
        } => {
            let kinds: Vec<scenes::Bench> = match scene.as_deref() {
                None => vec![scenes::Bench::Game, scenes::Bench::Dense],
                Some("game") => vec![scenes::Bench::Game],
                Some("dense") => vec![scenes::Bench::Dense],
                Some(o) => anyhow::bail!("--scene: unknown scene {o:?} (game, dense)"),
            };
            let rows_sel: Vec<scenes::Row> = match row.as_deref() {
                None => scenes::Row::ALL.to_vec(),
                Some(r) => vec![scenes::Row::ALL
                    .into_iter()
                    .find(|x| x.label().replace(" x", "") == r)
                    .ok_or_else(|| anyhow::anyhow!("--row: unknown row {r:?} (static, motion, motion2, defocus, defocus2, both, both2)"))?],
            };
            let rows = bench::run_table(
                quick,
                &kinds,
                &rows_sel,
                tile_sweep,
                (!no_limit).then_some(bench::ORACLE_DENSITY),
            );
            print!("{}", bench::table_md(&rows));
            if let Some(p) = json {
                std::fs::write(&p, serde_json::to_string_pretty(&rows)? + "\n")?;
            }
        }
        Cmd::Converge {
            scene,
            out,
            repeats,
        } => {
            let s = match scene {
                Some(p) => Scene::load(&p)?,
                None => scenes::default_scene(),
            };
            let pts = uvt_host::converge::sweep(&s, repeats)?;
            print!("{}", uvt_host::converge::table_md(&pts));
            for f in uvt_host::converge::write(&pts, &s, &out)? {
                println!("wrote {}", f.display());
            }
        }
        Cmd::Precision { quick, out, replot } => {
            let sw = if quick {
                uvt_host::precision::Sweep {
                    scenes: vec![scenes::Bench::Game, scenes::Bench::Dense],
                    rows: vec![scenes::Row::Static, scenes::Row::Both],
                    tiles: vec![1, 2, 4, 8],
                    shrink: 2,
                }
            } else {
                uvt_host::precision::Sweep {
                    scenes: vec![scenes::Bench::Game, scenes::Bench::Dense],
                    rows: scenes::Row::ALL.to_vec(),
                    tiles: vec![1, 2, 4, 8],
                    shrink: 1,
                }
            };
            let rows: Vec<uvt_host::precision::PrecRow> = match replot {
                Some(p) => serde_json::from_str(&std::fs::read_to_string(&p)?)
                    .map_err(|e| anyhow::anyhow!("{}: not a precision.json: {e}", p.display()))?,
                None => uvt_host::precision::sweep(&sw),
            };
            let md = uvt_host::precision::table_md(&rows);
            std::fs::create_dir_all(&out)?;
            std::fs::write(out.join("precision.md"), &md)?;
            std::fs::write(
                out.join("precision.json"),
                serde_json::to_string_pretty(&rows)? + "\n",
            )?;
            uvt_host::precision::plot_svg(&rows, &out.join("precision.svg"))?;
            print!("{md}");
        }
        Cmd::Stress { dir } => {
            let scenes = uvt_host::precision::stress_scenes(&dir)?;
            let rows: Vec<_> = scenes
                .iter()
                .map(|s| {
                    (
                        s.name.clone(),
                        s.tris.len(),
                        uvt_host::precision::stress_row(s),
                    )
                })
                .collect();
            print!("{}", uvt_host::precision::stress_md(&rows));
            let bad: Vec<_> = rows
                .iter()
                .filter(|r| r.2.violations > 0 || r.2.beyond_bound > 0)
                .map(|r| r.0.clone())
                .collect();
            if !bad.is_empty() {
                anyhow::bail!(
                    "conservativeness or error-bound failures in: {}",
                    bad.join(", ")
                );
            }
        }
        Cmd::Vectors(VecCmd::Export { scene, out, seed }) => {
            match scene {
                Some(p) => uvt_host::vectors::export_scene(&p, &out)?,
                None => uvt_host::vectors::export_default(&out, seed)?,
            }
            println!("wrote vectors to {}", out.display());
        }
        Cmd::Vectors(VecCmd::Check { dir }) => {
            let c = uvt_host::vectors::check::check(&dir)?;
            for s in &c.sets {
                println!("ok {}", s.display());
            }
            println!("{} records match the core bit for bit", c.records);
        }
        Cmd::Vectors(VecCmd::Layout) => {
            for st in uvt_host::vectors::format::STAGES {
                for io in ["in", "out"] {
                    let spp = if st == "resolve" { 4 } else { 0 };
                    println!(
                        "{}",
                        uvt_host::vectors::format::layout_md(&format!("{st}_{io}"), spp)
                    );
                }
            }
        }
    }
    Ok(())
}
