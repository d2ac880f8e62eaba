//! The command line of `uvt`: every command and option (clap). Names of configurations and
//! bounds strategies are checked against the core's registries where the command runs
//! (`uvt_host::config::names`).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use uvt_host::config::names;

#[derive(Parser)]
#[command(
    name = "uvt",
    version,
    about = "uvt: bit-accurate stochastic rasterizer reference model, host tools"
)]
pub struct Cli {
    #[command(subcommand)]
    pub cmd: Cmd,
}

#[derive(Subcommand)]
pub enum Cmd {
    /// Render a scene (default: the built-in scene) with the core and the f64 reference.
    Render {
        /// scene file (JSON, format in host/scenes/README.md); omitted: the built-in default
        /// scene with motion and defocus
        scene: Option<PathBuf>,
        /// output directory (created if absent)
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// how the core runs the frame: samples per pixel, bounds tile, viewport, strategy
        #[command(flatten)]
        frame: FrameArgs,
        /// sample pattern seed (overrides the scene file)
        #[arg(long)]
        seed: Option<u64>,
        /// the core's configuration: `default` (bounded-16-16-16-20) or any name of `uvt
        /// configs` (e.g. exact-12-12-8); the f64 reference stays exact
        #[arg(long, default_value = names::DEFAULT_ALIAS)]
        precision: String,
        /// memory budget of the scene, e.g. 512M or 8G (estimate in host/src/scene/budget.rs)
        #[arg(long, default_value = "4G")]
        mem_budget: String,
    },
    /// Built-in scenes.
    #[command(subcommand)]
    Scene(SceneCmd),
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
        /// skip the axis-aligned limit (its search takes most of the run)
        #[arg(long)]
        no_limit: bool,
        /// the axis-aligned limit's two efforts, low and high, each dense points per pixel and
        /// face-search proposals per face: `D0:S0,D1:S1` (default 16:16,64:64); the search runs
        /// in (u, v, t) with a 2D clip per point, seeds on the tile's centre line and line pushes
        /// of every face (host/src/oracle/)
        #[arg(long)]
        limit_effort: Option<String>,
        /// the core's configuration: `default` or any name of `uvt configs` (the f64 reference
        /// and the axis-aligned limit stay exact)
        #[arg(long, default_value = names::DEFAULT_ALIAS)]
        precision: String,
    },
    /// Every bounds strategy with and without Zmax culling on the occlusion rows (the game
    /// street behind a near fence) and the open game rows: sample tests, tiles skipped, whole
    /// ops, whole Cortex-M4F instructions (Zmax's own included) and wall time; fails if an image
    /// differs with Zmax
    BenchZmax {
        /// quarter resolution and tessellation
        #[arg(long)]
        quick: bool,
        /// also write the rows as JSON here
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// Write a bench row's own work (triangles, sample table, viewport; bounds tile 1) as the
    /// Cortex-M strategy harness takes it (demo/examples/m4_stages; `bash demo/m4_report.sh
    /// --strategies` runs it for every row).
    M4Workload {
        /// bench scene: game or dense
        #[arg(long)]
        scene: String,
        /// bench row: static, motion, motion2, defocus, defocus2, both, both2
        #[arg(long)]
        row: String,
        /// the quick size (a quarter of the resolution and tessellation)
        #[arg(long)]
        quick: bool,
        /// keep every N-th triangle of the row (from the first)
        #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
        every: u32,
        /// output file
        #[arg(long)]
        out: PathBuf,
    },
    /// Derive the rule of the `auto` bounds strategy from the Cortex-M4F stage costs and write
    /// it as Rust source (core/src/bounds/auto/rule.rs).
    AutoRule {
        /// the stage costs (`bash demo/m4_report.sh --strategies` writes them)
        #[arg(long, default_value = uvt_host::bench::m4_stages::DEFAULT_PATH)]
        m4: PathBuf,
        /// output file
        #[arg(long, default_value = "core/src/bounds/auto/rule.rs")]
        out: PathBuf,
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
        /// shrink the benchmark scenes by this factor beyond the quick size (default: 2 with
        /// --quick, 1 without; a larger factor gives a tiny run)
        #[arg(long)]
        shrink: Option<u16>,
        /// Cortex-M4F instruction counts per configuration (`bash demo/m4_report.sh --sweep`
        /// writes it); its columns show "–" when the file does not exist
        #[arg(long, default_value = "host/report/m4.json")]
        m4: PathBuf,
        /// synthesis results (vectors/rtl's synthesis script writes it); optional
        #[arg(long, default_value = "host/report/synth.json")]
        synth: PathBuf,
        /// only these configurations (comma-separated names of `uvt configs`, e.g.
        /// exact-16-16-16,planar-16-16-16-20); default: the sweep (`uvt configs --sweep`) and
        /// the planar configuration
        #[arg(long)]
        configs: Option<String>,
    },
    /// Print the derived bit-width table (Markdown) of a configuration; without --config the
    /// width section of core/README.md (the exact and the default configuration).
    Widths {
        /// configuration name: exact-P-T-B or bounded-P-T-B-O, any in range (e.g.
        /// bounded-12-12-12-24); not planar-…
        #[arg(long)]
        config: Option<String>,
    },
    /// The hardware multiplier cost model (from the width table): totals per sweep
    /// configuration and stage, or every multiplier of one configuration; with --strategies
    /// the width-weighted figure of every bounds strategy's stages (at --config, default
    /// bounded-16-16-16-20).
    Cost {
        /// configuration name (exact-P-T-B or bounded-P-T-B-O, any in range; not planar-…);
        /// omitted: the sweep's totals
        #[arg(long)]
        config: Option<String>,
        /// every bounds strategy's operators per triangle, tile, row span and sample, weighted
        /// by width (DSP48E1, MULT18X18D, adder, compare and divider bits)
        #[arg(long)]
        strategies: bool,
    },
    /// Which unit a scene needs: the smallest unit variant, the narrowest configuration whose
    /// error statement meets the tolerance (pixels, or clip units for primitives stated in clip
    /// space only), the cheapest bounds strategy and tile size;
    /// then a confirming render (exit status non-zero if a confirmation fails). Writes
    /// DIR/fit.md and DIR/fit.json.
    Fit {
        /// scene file (JSON, format in host/scenes/README.md)
        scene: PathBuf,
        /// largest allowed distance (px) from an edge of a decision differing from the exact
        /// image (default 1/32 px; host/src/fit/select.rs says why)
        #[arg(long, allow_hyphen_values = true)]
        tolerance: Option<String>,
        /// the tolerance for primitives stated in clip space only (a vertex can reach the camera
        /// plane): the largest vertex move, in clip units, of the triangle whose exact decisions
        /// the configuration's must equal (default 2·tolerance/max(W, H): the tolerance in
        /// pixels for a vertex at w = 1; host/src/config/dq.rs)
        #[arg(long, allow_hyphen_values = true)]
        clip_tolerance: Option<String>,
        /// output directory for fit.md and fit.json
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Cortex-M4F figures per unit (`bash demo/m4_report.sh --units` writes it); "not
        /// measured" when absent
        #[arg(long, default_value = "host/report/m4_units.json")]
        m4_units: PathBuf,
        /// Cortex-M4F figures per unit at the planar configuration (`bash demo/m4_report.sh
        /// --units FILE planar-16-16-16-20`), used when fit picks it
        #[arg(long, default_value = "host/report/m4_units_planar.json")]
        m4_units_planar: PathBuf,
        /// memory budget of the scene, e.g. 512M or 8G
        #[arg(long, default_value = "4G")]
        mem_budget: String,
    },
    /// The Cortex-M4F unit programs' tables of docs/units.md from `m4_units.json` (`bash
    /// demo/m4_report.sh --units` writes it): flash, RAM, stack and instructions per call of
    /// each unit, against the full unit, and the full unit on each narrower unit's triangles.
    M4Units {
        /// the report (`host/report/m4_units_planar.json` for the planar configuration's)
        #[arg(default_value = "host/report/m4_units.json")]
        file: PathBuf,
    },
    /// The unit-variant table: per unit flash, RAM and M4F instructions (from m4_units.json),
    /// the sample test's multiplier estimate restricted to the unit's stages and the RTL unit's
    /// synthesized counts (from synth.json); then the static-only unit at the planar static
    /// configuration (estimate and synthesized uvt_psample.v).
    Units {
        /// configuration name (exact-P-T-B or bounded-P-T-B-O, any in range; not planar-…)
        #[arg(long, default_value = names::DEFAULT_NAME)]
        config: String,
        /// Cortex-M4F figures per unit
        #[arg(long, default_value = "host/report/m4_units.json")]
        m4_units: PathBuf,
        /// synthesized RTL unit variants (`bash vectors/rtl/synth.sh` writes it); "not
        /// synthesized" when absent
        #[arg(long, default_value = "host/report/synth.json")]
        synth: PathBuf,
    },
    /// Refresh the documentation's copies of reports: every block of README.md and docs/*.md
    /// between `<!-- report:begin FILE#SECTION … -->` and `<!-- report:end -->` becomes that
    /// section of the committed report (`table-N`: its N-th Markdown table; `all`: the whole
    /// file). With --block NAME --file PAGE, the block between `<!-- NAME:begin … -->` and
    /// `<!-- NAME:end -->` of PAGE becomes the standard input instead (host/report/regen.sh runs
    /// both).
    Splice {
        /// change nothing: list the report blocks that differ and fail if one does
        #[arg(long, conflicts_with = "block")]
        check: bool,
        /// the name of a block of --file to fill from the standard input (e.g. strategy-cost)
        #[arg(long, requires = "file")]
        block: Option<String>,
        /// the page holding --block
        #[arg(long, requires = "block")]
        file: Option<PathBuf>,
        /// the repository root (README.md, docs/ and the reports' paths are relative to it)
        #[arg(long, default_value = ".")]
        root: PathBuf,
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
    /// The named configurations (uvt_core::config::registry) every option and report takes:
    /// one line each — name, kind (exact, bounded, planar), `sweep` if the precision sweep runs
    /// it, `default` for the default.
    Configs {
        /// only the precision sweep's names, one per line (what `demo/m4_report.sh --sweep`
        /// runs)
        #[arg(long, conflicts_with = "strategies")]
        sweep: bool,
        /// the bounds strategies instead (uvt_core::bounds::registry), one per line
        #[arg(long)]
        strategies: bool,
    },
}

/// The options of how the core runs a frame that `uvt render` and `uvt vectors export --scene`
/// share (one definition, so a frame trace can be taken of exactly what `render` ran).
#[derive(Args)]
pub struct FrameArgs {
    /// samples per pixel, 1..=64 (overrides the scene file)
    #[arg(long, allow_hyphen_values = true, value_parser = clap::value_parser!(u16).range(1..=64))]
    pub spp: Option<u16>,
    /// bounds tile size 1, 2, 4 or 8 (overrides the scene file)
    #[arg(long, allow_hyphen_values = true, value_parser = clap::value_parser!(u8).range(1..=8))]
    pub tile: Option<u8>,
    /// viewport WxH, e.g. 320x180 (overrides the scene file; the mesh form is re-projected)
    #[arg(long)]
    pub viewport: Option<String>,
    /// bounds strategy of the core: any of `uvt configs --strategies` (e.g. best)
    #[arg(long, default_value = "laine2011")]
    pub bounds: String,
}

#[derive(Subcommand)]
pub enum SceneCmd {
    /// List the built-in scenes.
    List,
    /// Write a built-in scene as a scene file (direct form, clip space) to stdout or --out.
    Export {
        /// scene name (see `uvt scene list`)
        name: String,
        /// write to this file instead of stdout
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

#[derive(Subcommand)]
pub enum VecCmd {
    /// Write vectors: without --scene the committed sets (unit/, unit_exact/, frame_a/,
    /// frame_b/) into DIR, or with --config the unit and frame sets at that configuration; with
    /// --scene the frame set of that scene as `uvt render` runs it with the same --spp, --tile,
    /// --viewport and --bounds (bounds records for laine2011 only: the RTL bounds unit's).
    Export {
        /// frame-level vectors of this scene file only
        #[arg(long)]
        scene: Option<PathBuf>,
        /// how the core runs the frame (with --scene only), as for `uvt render`
        #[command(flatten)]
        frame: FrameArgs,
        /// configuration of every stage's records and the trace: `default` or a name of `uvt
        /// configs` (without --scene: unit/, frame_a/, frame_b/ at it; default: the committed
        /// sets)
        #[arg(long)]
        config: Option<String>,
        /// output directory
        #[arg(long)]
        out: PathBuf,
        /// seed of the unit-level random inputs
        #[arg(long, default_value_t = uvt_host::vectors::committed::DEFAULT_SEED)]
        seed: u64,
    },
    /// Re-run the core on the vectors in DIR and compare bit for bit.
    Check {
        /// a vector set, or a folder of sets
        dir: PathBuf,
    },
    /// Print the bit-layout tables of every file (Markdown).
    Layout,
    /// Write input records of a seeded stream to stdout, one per line: record i depends on
    /// (KIND, --config, --seed, i) only, so `--shard K/M` parts concatenate to the whole stream.
    Gen {
        /// record kind: bsample, psample, setup, select or resolve
        kind: String,
        /// configuration (a registry name; `uvt configs`); default: the kind's own
        #[arg(long)]
        config: Option<String>,
        /// stream seed
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// records in the whole stream
        #[arg(long)]
        count: u64,
        /// write only part K of M (contiguous; 1/1 = all)
        #[arg(long, default_value = "1/1")]
        shard: String,
        /// samples per resolve record
        #[arg(long, default_value_t = 16)]
        spp: u32,
        /// also write the model's coverage bins of the written records (bsample, psample) to
        /// this JSON file (`uvt vectors coverage` lists the bins)
        #[arg(long)]
        coverage: Option<PathBuf>,
        /// bias the stream toward these bins (comma-separated bin names; `uvt vectors coverage`
        /// lists them): still seeded and shard-invariant
        #[arg(long, value_delimiter = ',')]
        target_bins: Vec<String>,
    },
    /// Read input+output record pairs of KIND from stdin (one pair per line: the input words,
    /// then the output words) and compare each output with the model's; non-zero exit on any
    /// difference, naming the line and every differing field, and on fewer pairs than expected
    /// (none at all, or not --count).
    Ver {
        /// record kind: bsample, psample, setup, select or resolve
        kind: String,
        /// compare the architectural fields only (covered, depth; inside; setup's outputs
        /// before its Laine coefficients)
        #[arg(long)]
        arch_only: bool,
        /// the number of pairs expected (what was fed to the runner); another number fails.
        /// Omitted: at least one
        #[arg(long)]
        count: Option<u64>,
        /// samples per resolve record
        #[arg(long, default_value_t = 16)]
        spp: u32,
        /// also write the model's coverage bins of the checked inputs (bsample, psample) to
        /// this JSON file
        #[arg(long)]
        coverage: Option<PathBuf>,
    },
    /// Coverage per kind from the model's own bins (`uvt_core::coverage`): every bin, its
    /// count over the committed sets (unit/, unit_exact/, frame_a/, frame_b/) and over a seeded
    /// stream; unreachable bins apart with their reasons.
    Coverage {
        /// the folder of the committed sets
        #[arg(long, default_value = "vectors")]
        vectors: PathBuf,
        /// stream records per kind
        #[arg(long, default_value_t = 1_000_000)]
        count: u64,
        /// stream seed
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// write the report as JSON to this file
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// Decode one record field by field (hex and value) and show the model's output for an
    /// input record; given input and output words, the fields that differ from the model's
    /// (non-zero exit when the given output differs).
    Decode {
        /// a file stem (bsample_in, psample_out, …) or a kind (bsample: input, output or both)
        kind: String,
        /// the record's words in hex (as in the .hex files; one argument may hold several)
        #[arg(required = true, num_args = 1..)]
        words: Vec<String>,
    },
}
