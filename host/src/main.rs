//! `uvt`: command-line tools of the uvt reference model. Bad input exits non-zero with a message
//! naming what is wrong.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand};
use uvt_host::{bench, render, scene::Scene, scenes};

#[derive(Parser)]
#[command(name = "uvt", version, about = "uvt: bit-accurate stochastic rasterizer reference model, host tools")]
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
    },
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
        Cmd::BenchSte { quick, json, scene, row } => {
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
            let rows = bench::run_table(quick, &kinds, &rows_sel);
            print!("{}", bench::table_md(&rows));
            if let Some(p) = json {
                std::fs::write(&p, serde_json::to_string_pretty(&rows)? + "\n")?;
            }
        }
    }
    Ok(())
}
