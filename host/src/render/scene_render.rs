//! `uvt render`: one scene with the core (its bounds strategy, Laine 2011 by default, and the
//! bounding-box scan) and with the f64 reference; PNGs, a Markdown and a JSON report. Files are written to temporary names and
//! renamed, so a failed run leaves no half-written output.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, Context, Result};
use uvt_core::bounds::any::AnyStrategy;
use uvt_core::{with_config, BboxScan, NoZmax, Precision};

use crate::bench::strategy::run_frame;
use crate::compare::pass::{compare, Spec};
use crate::config::dq::statements;
use crate::config::rounding::Rounding;
use crate::frame::opts::RunOpts;
use crate::frame::reference::run_reference;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;

use super::opts::{RenderOpts, Rendered};
use super::report::{report_json, report_md};
use super::{diff, heatmap};

/// Render a scene with all pipelines at the default options.
pub fn render(scene: &Scene) -> Result<Rendered> {
    render_with(scene, &RenderOpts::default())
}

/// Render a scene with all pipelines, the core at `o.precision` with `o.bounds` (any
/// configuration of the registry, any strategy of its list).
pub fn render_with(scene: &Scene, o: &RenderOpts) -> Result<Rendered> {
    with_config!(o.precision, P => pipelines::<P>(scene, o))
        .ok_or_else(|| anyhow!("configuration {} is not in the registry", o.precision))?
}

fn pipelines<P: Precision + Sync>(scene: &Scene, o: &RenderOpts) -> Result<Rendered> {
    let say = |k: u32, what: &str| {
        if o.progress {
            crate::log::line(&format!("render: [{k}/4] {what}"));
        }
    };
    let exact = Pattern::new(scene.pattern, scene.spp, scene.seed);
    let (core, pattern) = scene.inputs_at::<P>()?;
    let vp = scene.core_viewport();
    let colors = scene.colors();
    let opts = |label| RunOpts {
        clear: [24, 24, 32],
        image: true,
        label,
        ..RunOpts::for_scene(scene, &colors)
    };
    say(1, "core with its bounds, and the oracle's dense sampling");
    let fixed_opts = RunOpts {
        oracle: Some(&scene.tris),
        ..opts("uvt fixed")
    };
    // The strategy by name (`AnyStrategy`: its own code, one instance per configuration).
    let strategy = AnyStrategy::named(o.bounds)
        .ok_or_else(|| anyhow!("unknown bounds strategy {:?}", o.bounds))?;
    let fixed = run_frame::<_, P, NoZmax>(strategy, vp, &core, &pattern, &fixed_opts)?;
    say(2, "f64 reference");
    let f64 = run_reference(&scene.tris, &exact, &opts("uvt f64"));
    say(3, "core with the bounding-box scan");
    let bbox = run_frame::<_, P, NoZmax>(BboxScan, vp, &core, &pattern, &opts("bbox scan"))?;
    say(4, "comparing core and reference sample by sample");
    let rounding = Rounding::at(P::POS_FRAC, P::TUV_FRAC);
    let stated = statements::<P>(&scene.tris, &core, vp, &rounding, 1.0);
    let spec = Spec {
        strategy,
        tiles: vec![scene.tile],
        statements: stated,
        tolerance: None,
        rounding,
    };
    let coverage = compare::<P, _>(&scene.tris, &core, vp, &pattern, &spec);
    let report = report_json(scene, o, &fixed, &f64, &bbox, &coverage);
    Ok(Rendered {
        fixed,
        f64,
        bbox,
        coverage,
        opts: *o,
        report,
    })
}

fn png(path: &Path, w: u16, h: u16, px: &[[u8; 3]]) -> Result<()> {
    let buf: Vec<u8> = px.iter().flatten().copied().collect();
    let img = image::RgbImage::from_raw(w as u32, h as u32, buf).context("image size")?;
    img.save_with_format(path, image::ImageFormat::Png)
        .with_context(|| format!("writing {}", path.display()))
}

/// `dir` is usable as an output directory: absent (it will be created) or a directory.
pub fn check_out_dir(dir: &Path) -> Result<()> {
    match std::fs::metadata(dir) {
        Ok(m) if !m.is_dir() => Err(anyhow!(
            "--out {}: exists and is not a directory",
            dir.display()
        )),
        _ => Ok(()),
    }
}

/// Write all outputs into `dir` (created if needed); temp names, then renames.
pub fn write(r: &Rendered, scene: &Scene, dir: &Path) -> Result<Vec<PathBuf>> {
    check_out_dir(dir)?;
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let (w, h) = scene.viewport;
    let diff = diff::draw(w, h, &diff::differences(&r.fixed.image, &r.f64.image));
    let heat = heatmap::draw(w, h, &r.fixed.heat, diff::scale_for(w, h));
    type Writer<'a> = Box<dyn Fn(&Path) -> Result<()> + 'a>;
    let files: Vec<(&str, Writer<'_>)> = vec![
        (
            "fixed.png",
            Box::new(|p: &Path| png(p, w, h, &r.fixed.image)),
        ),
        ("f64.png", Box::new(|p: &Path| png(p, w, h, &r.f64.image))),
        (
            "diff.png",
            Box::new(|p: &Path| {
                diff.save_with_format(p, image::ImageFormat::Png)
                    .with_context(|| format!("writing {}", p.display()))
            }),
        ),
        (
            "heat.png",
            Box::new(|p: &Path| {
                heat.save_with_format(p, image::ImageFormat::Png)
                    .with_context(|| format!("writing {}", p.display()))
            }),
        ),
        (
            "report.json",
            Box::new(|p: &Path| {
                Ok(std::fs::write(
                    p,
                    serde_json::to_string_pretty(&r.report)? + "\n",
                )?)
            }),
        ),
        (
            "report.md",
            Box::new(|p: &Path| Ok(std::fs::write(p, report_md(r))?)),
        ),
    ];
    let mut tmp = Vec::new();
    for (name, f) in &files {
        let t = dir.join(format!(".{name}.tmp"));
        if let Err(e) = f(&t) {
            for t in tmp.iter().chain(std::iter::once(&t)) {
                let _ = std::fs::remove_file(t);
            }
            return Err(e);
        }
        tmp.push(t);
    }
    let mut out = Vec::new();
    for ((name, _), t) in files.iter().zip(tmp) {
        let dst = dir.join(name);
        std::fs::rename(&t, &dst).with_context(|| format!("renaming to {}", dst.display()))?;
        out.push(dst);
    }
    Ok(out)
}
