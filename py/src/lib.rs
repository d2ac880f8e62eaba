//! `uvt._uvt`: the native part of the Python module `uvt` (py/python/uvt). Every list it
//! exposes — configurations, bounds strategies, record kinds — is read from the Rust registries
//! (`uvt_core::config::registry`, `uvt_core::bounds::registry::STRATEGIES`, `uvt_records::kind`),
//! and every operation calls the one Rust implementation the C library and the `uvt` command
//! call: the typed sample test of `uvt_records::typed`, the record codec and streams of
//! `uvt_records`, the renderer of `uvt_host::render`. The Python package checks argument types
//! and shapes and converts arrays; this module runs the model, releasing the GIL in every batch
//! call, and turns the model's refusals into `uvt.InputError` / `uvt.ConfigError` (both
//! `uvt.UvtError`, a `ValueError`) whose message names the field and its raw bits.
//!
//! No `unsafe` of its own: PyO3's macros generate the boundary (and catch panics there).

#![forbid(unsafe_code)]
#![deny(missing_docs)]

use std::path::Path;

use numpy::ndarray::Array2;
use numpy::{
    PyArray1, PyArray2, PyArray3, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods,
};
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::config::registry::{self, CONFIGS};
use uvt_records::format::{field_value, layout, RecField};
use uvt_records::kind::{self, Kind};
use uvt_records::stream::{Shard, Stream};
use uvt_records::typed::{Hit as RHit, Tri, TypedError, TRI_WORDS};

create_exception!(
    uvt,
    UvtError,
    PyValueError,
    "A call the uvt model refuses: the base of uvt.InputError and uvt.ConfigError (a ValueError)."
);
create_exception!(
    uvt,
    InputError,
    UvtError,
    "An input the model refuses: a field out of its domain or off its configuration's grid, a culled triangle, an unknown record kind, a record of the wrong length; the message names the field and its raw bits."
);
create_exception!(
    uvt,
    ConfigError,
    UvtError,
    "An unknown configuration or bounds strategy, or one the operation is not made at (the typed test at an exact configuration)."
);

fn input_err(msg: impl Into<String>) -> PyErr {
    InputError::new_err(msg.into())
}

fn config_err(msg: impl Into<String>) -> PyErr {
    ConfigError::new_err(msg.into())
}

fn typed_err(e: TypedError) -> PyErr {
    match e {
        TypedError::Config(m) => config_err(m),
        TypedError::Input(m) => input_err(m),
    }
}

/// An integer argument in `lo..=hi`, else InputError naming it.
fn in_range(what: &str, v: i64, lo: i64, hi: i64) -> PyResult<i64> {
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(input_err(format!("{what} = {v}: outside {lo}..={hi}")))
    }
}

/// The kind named `name`; InputError listing the names otherwise.
fn kind_of(name: &str) -> PyResult<Kind> {
    Kind::parse(name).map_err(input_err)
}

/// The result of one sample test (`Triangle.test`).
#[pyclass(frozen, eq, module = "uvt")]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hit {
    hit: RHit,
}

#[pymethods]
impl Hit {
    /// True when the sample is covered.
    #[getter]
    fn covered(&self) -> bool {
        self.hit.covered
    }
    /// Orientation: the bounded test's sign of Σ E'·w, the planar test's σ (−1, 0 or 1).
    #[getter]
    fn det_sign(&self) -> i32 {
        self.hit.det_sign
    }
    /// Depth, raw with 24 fraction bits; 0 when not covered.
    #[getter]
    fn depth(&self) -> i32 {
        self.hit.depth
    }
    /// The three edge values (bounded: E'_k on the offset grid; planar: exact E_k), raw.
    #[getter]
    fn e(&self) -> (i64, i64, i64) {
        (self.hit.e[0], self.hit.e[1], self.hit.e[2])
    }
    fn __repr__(&self) -> String {
        format!(
            "Hit(covered={}, det_sign={}, depth={}, e=({}, {}, {}))",
            if self.hit.covered { "True" } else { "False" },
            self.hit.det_sign,
            self.hit.depth,
            self.hit.e[0],
            self.hit.e[1],
            self.hit.e[2]
        )
    }
}

/// A triangle set up once at one configuration; its sample test, one sample (`test`) or many
/// (`test_batch`, in the Python package). The same computation as the C library's
/// `uvt_tri_new` / `uvt_tri_sample`.
#[pyclass(subclass, frozen, module = "uvt")]
pub struct Triangle {
    tri: Tri,
    config: &'static str,
    viewport: (u16, u16),
}

#[pymethods]
impl Triangle {
    /// `vertices`: 30 raw 16.16 words in the order (t0, t1) × 3 vertices × (x, y, z, w, coc),
    /// as a flat sequence of ints (the package's `uvt.Triangle` accepts a (2, 3, 5) array);
    /// `viewport`: (width, height) in pixels; `config`: a name of `uvt.CONFIGS` (None: the
    /// default).
    #[new]
    #[pyo3(signature = (vertices, viewport, config=None))]
    fn new(vertices: Vec<i64>, viewport: (i64, i64), config: Option<&str>) -> PyResult<Self> {
        if vertices.len() != TRI_WORDS {
            return Err(PyValueError::new_err(format!(
                "vertices: {} values, a triangle has {TRI_WORDS} (2 key frames × 3 vertices × x, y, z, w, coc)",
                vertices.len()
            )));
        }
        let mut w = [0u32; TRI_WORDS];
        const NAMES: [&str; 5] = ["x", "y", "z", "w", "coc"];
        for (i, v) in vertices.iter().enumerate() {
            let what = format!("vertices[{}][{}].{}", i / 15, i / 5 % 3, NAMES[i % 5]);
            // a raw 16.16 word: signed or its unsigned bit pattern
            let v = in_range(&what, *v, i64::from(i32::MIN), i64::from(u32::MAX))?;
            w[i] = v as u32;
        }
        let vw = in_range("viewport width", viewport.0, 0, i64::from(u16::MAX))? as u16;
        let vh = in_range("viewport height", viewport.1, 0, i64::from(u16::MAX))? as u16;
        let name = match config {
            None => registry::name_of(registry::DEFAULT).unwrap_or("default"),
            Some(n) => registry::find(n)
                .and_then(registry::name_of)
                .ok_or_else(|| config_err(format!("unknown configuration `{n}`")))?,
        };
        let tri = Tri::new(&w, vw, vh, Some(name)).map_err(typed_err)?;
        Ok(Triangle {
            tri,
            config: name,
            viewport: (vw, vh),
        })
    }

    /// The triangle's class: 0 static, 1 motion, 2 defocus, 3 both (bit 0 motion, bit 1
    /// defocus), as the C library's `uvt_tri_class`.
    #[getter]
    fn cls(&self) -> u32 {
        self.tri.class().index() as u32
    }

    /// The configuration's registry name.
    #[getter]
    fn config(&self) -> &'static str {
        self.config
    }

    /// The viewport (width, height).
    #[getter]
    fn viewport(&self) -> (u16, u16) {
        self.viewport
    }

    /// True when the planar test runs (a planar configuration's static triangle).
    #[getter]
    fn planar(&self) -> bool {
        self.tri.planar()
    }

    /// The sample test at position (`xs`, `ys`) in 1/256 px and `t`, `u`, `v` (raw, 16
    /// fraction bits, on the configuration's grid; ignored by the planar test): a `Hit`.
    /// InputError when the model refuses the sample (the message names the field).
    fn test(&self, xs: i64, ys: i64, t: i64, u: i64, v: i64) -> PyResult<Hit> {
        let p = |w, x| in_range(w, x, 0, i64::from(u32::MAX)).map(|x| x as u32);
        let s = |w, x| in_range(w, x, i64::from(i32::MIN), i64::from(i32::MAX)).map(|x| x as i32);
        let hit = self
            .tri
            .sample(
                p("xs", xs)?,
                p("ys", ys)?,
                s("t", t)?,
                s("u", u)?,
                s("v", v)?,
            )
            .map_err(typed_err)?;
        Ok(Hit { hit })
    }

    /// The batch sample test on contiguous arrays of equal length (xs, ys: uint32; t, u, v:
    /// int32), without the GIL: (covered uint8, det_sign int8, depth int32, e (n, 3) int64).
    /// The package's `Triangle.test_batch` converts and checks the arrays first.
    #[allow(clippy::type_complexity)]
    fn _test_batch<'py>(
        &self,
        py: Python<'py>,
        xs: PyReadonlyArray1<'py, u32>,
        ys: PyReadonlyArray1<'py, u32>,
        t: PyReadonlyArray1<'py, i32>,
        u: PyReadonlyArray1<'py, i32>,
        v: PyReadonlyArray1<'py, i32>,
    ) -> PyResult<(
        Bound<'py, PyArray1<u8>>,
        Bound<'py, PyArray1<i8>>,
        Bound<'py, PyArray1<i32>>,
        Bound<'py, PyArray2<i64>>,
    )> {
        let (xs, ys, t, u, v) = (
            xs.as_slice()?,
            ys.as_slice()?,
            t.as_slice()?,
            u.as_slice()?,
            v.as_slice()?,
        );
        let n = xs.len();
        if [ys.len(), t.len(), u.len(), v.len()]
            .iter()
            .any(|&l| l != n)
        {
            return Err(PyValueError::new_err(
                "xs, ys, t, u, v: arrays of different lengths",
            ));
        }
        let tri = &self.tri;
        let out = py.detach(move || {
            let mut cov = vec![0u8; n];
            let mut sign = vec![0i8; n];
            let mut depth = vec![0i32; n];
            let mut e = vec![0i64; 3 * n];
            for i in 0..n {
                let h = tri
                    .sample(xs[i], ys[i], t[i], u[i], v[i])
                    .map_err(|err| (i, err))?;
                cov[i] = u8::from(h.covered);
                sign[i] = h.det_sign as i8;
                depth[i] = h.depth;
                e[3 * i..3 * i + 3].copy_from_slice(&h.e);
            }
            Ok((cov, sign, depth, e))
        });
        let (cov, sign, depth, e) = out.map_err(|(i, err)| match err {
            TypedError::Input(m) => input_err(format!("sample {i}: {m}")),
            TypedError::Config(m) => config_err(m),
        })?;
        let e =
            Array2::from_shape_vec((n, 3), e).map_err(|x| PyValueError::new_err(x.to_string()))?;
        Ok((
            PyArray1::from_vec(py, cov),
            PyArray1::from_vec(py, sign),
            PyArray1::from_vec(py, depth),
            PyArray2::from_owned_array(py, e),
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "Triangle(cls={}, config='{}', viewport={:?})",
            self.tri.class().index(),
            self.config,
            self.viewport
        )
    }
}

/// The configurations of the registry, in its order: (name, kind, pos_frac, tuv_frac,
/// bnd_frac, offset shift or None, planar, in the precision sweep).
#[pyfunction]
#[allow(clippy::type_complexity)]
fn configs() -> Vec<(
    &'static str,
    &'static str,
    u32,
    u32,
    u32,
    Option<u32>,
    bool,
    bool,
)> {
    CONFIGS
        .iter()
        .map(|e| {
            let c = e.config;
            let kind = match (c.off(), c.planar()) {
                (None, _) => "exact",
                (Some(_), false) => "bounded",
                (Some(_), true) => "planar",
            };
            (
                e.name,
                kind,
                c.pos(),
                c.tuv(),
                c.bnd(),
                c.off(),
                c.planar(),
                e.sweep,
            )
        })
        .collect()
}

/// The default configuration's registry name.
#[pyfunction]
fn default_config() -> &'static str {
    registry::name_of(registry::DEFAULT).unwrap_or("default")
}

/// The bounds strategies of the registry, in its order.
#[pyfunction]
fn strategies() -> Vec<&'static str> {
    STRATEGIES.to_vec()
}

/// The record kinds in code order: (name, code, input words or None (resolve: one per
/// sample), output words, needs a setup_in record, architectural fields or None (all)).
#[pyfunction]
#[allow(clippy::type_complexity)]
fn kinds() -> Vec<(
    &'static str,
    u32,
    Option<u32>,
    u32,
    bool,
    Option<Vec<&'static str>>,
)> {
    Kind::ALL
        .iter()
        .map(|k| {
            let inw = (*k != Kind::Resolve).then(|| k.words_in(0));
            (
                k.name(),
                k.code(),
                inw,
                k.words_out(),
                k.needs_setup(),
                k.architectural().map(|a| a.to_vec()),
            )
        })
        .collect()
}

/// A field of a layout: (name, word, bit, width, signed, frac).
type FieldRow = (String, u32, u32, u32, bool, u32);

/// The fields of record file `file` (e.g. `bsample_out`; `spp` words for resolve) as (name,
/// word, bit, width, signed, frac).
#[pyfunction]
#[pyo3(signature = (file, spp=16))]
fn fields(file: &str, spp: u32) -> PyResult<Vec<FieldRow>> {
    let stem = file
        .strip_suffix("_in")
        .or_else(|| file.strip_suffix("_out"))
        .unwrap_or("");
    kind_of(stem).map_err(|_| {
        input_err(format!(
            "unknown record file `{file}` (a kind name with _in or _out)"
        ))
    })?;
    Ok(layout(file, spp)
        .fields
        .into_iter()
        .map(|f| (f.name, f.word, f.bit, f.width, f.signed, f.frac))
        .collect())
}

/// The record indices (start, end) of shard K of M of a stream of `count` records: the
/// records `gen` returns for it (`uvt_records::stream::Shard::range`).
#[pyfunction]
fn shard_range(count: u64, k: u64, m: u64) -> PyResult<(u64, u64)> {
    let r = Shard::new(k, m).map_err(input_err)?.range(count);
    Ok((r.start, r.end))
}

/// The configuration the stream of `kind` at `config` (None: the kind's default) is made at
/// (None for kinds without one), or the stream's refusal (`uvt_records::stream::Stream::new`).
#[pyfunction]
#[pyo3(signature = (kind, config=None))]
fn stream_config(kind: &str, config: Option<&str>) -> PyResult<Option<String>> {
    let k = kind_of(kind)?;
    let s = Stream::new(k, config, 0, 16).map_err(|e| {
        if k.needs_setup() {
            input_err(e)
        } else {
            config_err(e)
        }
    })?;
    Ok(s.config())
}

/// Input records of the seeded stream (kind, config, seed): indices of shard `shard` = (K, M)
/// of `count` records (None: all), `spp` samples per resolve record; (n, in_words) uint32.
/// The same records as `uvt vectors gen --shard K/M` and the C library's `uvt_gen`; `target`:
/// bin names to bias the stream toward (`uvt vectors gen --target-bins`; still seeded and
/// shard-invariant).
#[pyfunction]
#[pyo3(signature = (kind, config, seed, count, shard=None, spp=16, target=None))]
#[allow(clippy::too_many_arguments)]
fn gen<'py>(
    py: Python<'py>,
    kind: &str,
    config: Option<&str>,
    seed: u64,
    count: u64,
    shard: Option<(u64, u64)>,
    spp: u32,
    target: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyArray2<u32>>> {
    let k = kind_of(kind)?;
    let sh = match shard {
        None => Shard::ALL,
        Some((a, b)) => Shard::new(a, b).map_err(input_err)?,
    };
    if k == Kind::Resolve {
        kind::resolve_spp(spp as usize).map_err(input_err)?;
    }
    let s = Stream::new(k, config, seed, spp).map_err(|e| {
        if k.needs_setup() {
            input_err(e)
        } else {
            config_err(e)
        }
    })?;
    let s = s
        .targeting(target.as_deref().unwrap_or(&[]))
        .map_err(input_err)?;
    let range = sh.range(count);
    let n = usize::try_from(range.end - range.start)
        .map_err(|_| input_err(format!("count = {count}: too many records")))?;
    let w = k.words_in(spp) as usize;
    let words = py.detach(|| {
        let mut words = Vec::with_capacity(n * w);
        for i in range {
            words.extend_from_slice(&s.record(i).0 .0);
        }
        words
    });
    if words.len() != n * w {
        return Err(input_err(format!(
            "the {kind} stream's records are not {w} words"
        )));
    }
    let a = Array2::from_shape_vec((n, w), words).map_err(|e| input_err(e.to_string()))?;
    Ok(PyArray2::from_owned_array(py, a))
}

/// The records' rows, checked against the kind's lengths.
fn rows<'a>(a: &'a PyReadonlyArray2<'_, u32>, what: &str) -> PyResult<(Vec<&'a [u32]>, usize)> {
    let s = a.as_slice()?;
    let shape = a.shape();
    let (n, w) = (shape[0], shape[1]);
    if w == 0 && n > 0 {
        return Err(PyValueError::new_err(format!("{what}: rows of 0 words")));
    }
    Ok((
        if w == 0 {
            Vec::new()
        } else {
            s.chunks(w).collect()
        },
        w,
    ))
}

/// The setup_in rows (one per record, or one for all) of a bounds or exact sample-test record.
fn setups<'a>(
    k: Kind,
    n: usize,
    setup: &'a Option<PyReadonlyArray2<'_, u32>>,
) -> PyResult<Vec<Option<&'a [u32]>>> {
    match setup {
        None => Ok(vec![None; n]),
        Some(a) => {
            let (r, _) = rows(a, "setup")?;
            match r.len() {
                1 => Ok(vec![Some(r[0]); n]),
                m if m == n => Ok(r.into_iter().map(Some).collect()),
                m => Err(PyValueError::new_err(format!(
                    "setup: {m} setup_in records for {n} {} records (give one, or one per record)",
                    k.name()
                ))),
            }
        }
    }
}

/// The model on every input record, without the GIL: the output records, or (record index,
/// message) of the first it refuses.
fn run_all(k: Kind, ins: &[&[u32]], setup: &[Option<&[u32]>]) -> Result<Vec<u32>, (usize, String)> {
    let mut out = Vec::with_capacity(ins.len() * k.words_out() as usize);
    for (i, r) in ins.iter().enumerate() {
        let o = kind::run(k, r, setup[i]).map_err(|e| (i, e))?;
        out.extend_from_slice(&o.0);
    }
    Ok(out)
}

/// The model's output records for input records `inputs` ((n, in_words) uint32) of `kind`;
/// `setup` the setup_in records of bounds/sample records ((1 or n, 32) uint32).
#[pyfunction]
#[pyo3(signature = (kind, inputs, setup=None))]
fn run<'py>(
    py: Python<'py>,
    kind: &str,
    inputs: PyReadonlyArray2<'py, u32>,
    setup: Option<PyReadonlyArray2<'py, u32>>,
) -> PyResult<Bound<'py, PyArray2<u32>>> {
    let k = kind_of(kind)?;
    let (ins, _) = rows(&inputs, "inputs")?;
    let st = setups(k, ins.len(), &setup)?;
    let out = py
        .detach(|| run_all(k, &ins, &st))
        .map_err(|(i, e)| input_err(format!("record {i}: {e}")))?;
    let w = k.words_out() as usize;
    let a = Array2::from_shape_vec((ins.len(), w), out).map_err(|e| input_err(e.to_string()))?;
    Ok(PyArray2::from_owned_array(py, a))
}

/// The model's coverage bins: (name, record kind, why unreachable or None), every bin of the
/// registry (`uvt_core::coverage`), or those of `kind`.
#[pyfunction]
#[pyo3(signature = (kind=None))]
fn coverage_bins(
    kind: Option<&str>,
) -> PyResult<Vec<(&'static str, &'static str, Option<&'static str>)>> {
    if let Some(k) = kind {
        kind_of(k)?;
    }
    Ok(uvt_core::coverage::Bin::ALL
        .iter()
        .filter(|b| kind.is_none_or(|k| b.kind() == k))
        .map(|b| (b.name(), b.kind(), b.unreachable()))
        .collect())
}

/// The bins the model's test takes deciding input records `inputs` ((n, in_words) uint32) of
/// `kind` (bsample or psample): {bin name: count} over every bin of the kind (zeros included).
/// The same counting as `uvt vectors gen|ver --coverage` and the C library's `uvt_coverage`.
#[pyfunction]
fn coverage<'py>(
    py: Python<'py>,
    kind: &str,
    inputs: PyReadonlyArray2<'py, u32>,
) -> PyResult<std::collections::BTreeMap<&'static str, u32>> {
    let k = kind_of(kind)?;
    if !uvt_records::coverage::has_bins(k) {
        return Err(input_err(format!(
            "records of kind {kind} have no coverage bins"
        )));
    }
    let (ins, _) = rows(&inputs, "inputs")?;
    let c = py
        .detach(|| uvt_records::coverage::records(k, ins.iter().copied()))
        .map_err(input_err)?;
    Ok(uvt_records::coverage::bins(k)
        .map(|b| (b.name(), c.get(b)))
        .collect())
}

/// A field's exact value as a Python int (fields wider than 128 bits included).
fn field_int<'py>(py: Python<'py>, f: &RecField, words: &[u32]) -> PyResult<Bound<'py, PyAny>> {
    let (v, rest) = field_value(f, words);
    let hi = v.into_pyobject(py)?.into_any();
    match rest {
        None => Ok(hi),
        Some(lo) => {
            let shift = 32 * (f.words() - 4);
            hi.call_method1("__lshift__", (shift,))?
                .call_method1("__or__", (lo,))
        }
    }
}

/// Model the input records and compare with the observed output records: (pairs, records
/// that differ, the first `max_mismatches` differing fields as (record, field, expected,
/// observed, message)); `architectural`: only the architectural fields (as `uvt_compare`).
#[pyfunction]
#[pyo3(signature = (kind, inputs, outputs, architectural=false, setup=None, max_mismatches=100))]
#[allow(clippy::too_many_arguments)]
fn compare<'py>(
    py: Python<'py>,
    kind: &str,
    inputs: PyReadonlyArray2<'py, u32>,
    outputs: PyReadonlyArray2<'py, u32>,
    architectural: bool,
    setup: Option<PyReadonlyArray2<'py, u32>>,
    max_mismatches: usize,
) -> PyResult<(usize, usize, Bound<'py, PyList>)> {
    let k = kind_of(kind)?;
    let (ins, _) = rows(&inputs, "inputs")?;
    let (obs, ow) = rows(&outputs, "outputs")?;
    if obs.len() != ins.len() {
        return Err(PyValueError::new_err(format!(
            "{} input records, {} output records",
            ins.len(),
            obs.len()
        )));
    }
    if !obs.is_empty() && ow != k.words_out() as usize {
        return Err(input_err(format!(
            "outputs: rows of {ow} words, a {}_out record has {}",
            k.name(),
            k.words_out()
        )));
    }
    let st = setups(k, ins.len(), &setup)?;
    let only = if architectural {
        k.architectural()
    } else {
        None
    };
    let file = format!("{}_out", k.name());
    let (exp, diffs, bad) = py
        .detach(|| {
            let exp = run_all(k, &ins, &st)?;
            let w = k.words_out() as usize;
            let mut diffs = Vec::new();
            let mut bad = 0;
            for (i, o) in obs.iter().enumerate() {
                let e = &exp[i * w..(i + 1) * w];
                let d = kind::diff_fields(&file, e, o, only);
                if !d.is_empty() {
                    bad += 1;
                }
                for f in d {
                    if diffs.len() < max_mismatches {
                        diffs.push((i, f));
                    }
                }
            }
            Ok((exp, diffs, bad))
        })
        .map_err(|(i, e): (usize, String)| input_err(format!("record {i}: {e}")))?;
    let w = k.words_out() as usize;
    let list = PyList::empty(py);
    for (i, d) in diffs {
        let e = &exp[i * w..(i + 1) * w];
        let t = PyTuple::new(
            py,
            [
                i.into_pyobject(py)?.into_any(),
                d.field.name.as_str().into_pyobject(py)?.into_any(),
                field_int(py, &d.field, e)?,
                field_int(py, &d.field, obs[i])?,
                d.message.as_str().into_pyobject(py)?.into_any(),
            ],
        )?;
        list.append(t)?;
    }
    Ok((ins.len(), bad, list))
}

/// Every field of one record of `file` (e.g. `bsample_in`) as a dict name → exact int.
fn fields_dict<'py>(py: Python<'py>, file: &str, words: &[u32]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for f in layout(file, words.len() as u32).fields {
        d.set_item(f.name.as_str(), field_int(py, &f, words)?)?;
    }
    Ok(d)
}

/// One record decoded: {"in": fields of the input record, "model": the model's output fields
/// (None when it refuses the record), "model_error": its message or None, and with
/// `out_words`: "out": their fields, "diff": the fields they differ from the model's in}.
#[pyfunction]
#[pyo3(signature = (kind, in_words, out_words=None, setup=None))]
fn decode<'py>(
    py: Python<'py>,
    kind: &str,
    in_words: PyReadonlyArray1<'py, u32>,
    out_words: Option<PyReadonlyArray1<'py, u32>>,
    setup: Option<PyReadonlyArray1<'py, u32>>,
) -> PyResult<Bound<'py, PyDict>> {
    let k = kind_of(kind)?;
    let i = in_words.as_slice()?;
    let spp = if k == Kind::Resolve {
        kind::resolve_spp(i.len()).map_err(input_err)?
    } else {
        0
    };
    if i.len() != k.words_in(spp) as usize {
        return Err(input_err(format!(
            "in_words: {} words, a {}_in record has {}",
            i.len(),
            k.name(),
            k.words_in(spp)
        )));
    }
    let s = match &setup {
        Some(a) => Some(a.as_slice()?),
        None => None,
    };
    let d = PyDict::new(py);
    d.set_item("kind", k.name())?;
    d.set_item("in", fields_dict(py, &format!("{}_in", k.name()), i)?)?;
    let model = kind::run(k, i, s);
    let file = format!("{}_out", k.name());
    match &model {
        Ok(r) => {
            d.set_item("model", fields_dict(py, &file, &r.0)?)?;
            d.set_item("model_error", py.None())?;
        }
        Err(e) => {
            d.set_item("model", py.None())?;
            d.set_item("model_error", e.as_str())?;
        }
    }
    if let Some(o) = &out_words {
        let o = o.as_slice()?;
        if o.len() != k.words_out() as usize {
            return Err(input_err(format!(
                "out_words: {} words, a {}_out record has {}",
                o.len(),
                k.name(),
                k.words_out()
            )));
        }
        d.set_item("out", fields_dict(py, &file, o)?)?;
        let diff: Vec<String> = match &model {
            Ok(r) => kind::diff(&file, &r.0, o, None),
            Err(_) => Vec::new(),
        };
        d.set_item("diff", diff)?;
    }
    Ok(d)
}

/// Render a scene as `uvt render` does (the same host code): `scene` a path, a JSON text
/// (starting with `{`) or None (the built-in default scene); `config` a configuration name;
/// `bounds` a strategy name; `spp`, `viewport` overrides. Returns (the core's image as an
/// (H, W, 3) uint8 array, report.json's text).
#[pyfunction]
#[pyo3(signature = (scene=None, config=None, bounds=None, spp=None, viewport=None))]
fn render<'py>(
    py: Python<'py>,
    scene: Option<&str>,
    config: Option<&str>,
    bounds: Option<&str>,
    spp: Option<i64>,
    viewport: Option<(i64, i64)>,
) -> PyResult<(Bound<'py, PyArray3<u8>>, String)> {
    use uvt_host::config::names;
    use uvt_host::render::opts::RenderOpts;
    use uvt_host::scene::builtin;
    use uvt_host::scene::file::{LoadOpts, Scene};
    let precision = names::precision("config", config.unwrap_or(names::DEFAULT_ALIAS))
        .map_err(|e| config_err(format!("{e:#}")))?;
    let bounds = names::strategy("bounds", bounds.unwrap_or("laine2011"))
        .map_err(|e| config_err(format!("{e:#}")))?;
    let spp = spp
        .map(|s| in_range("spp", s, 1, 64).map(|s| s as u16))
        .transpose()?;
    let viewport = viewport
        .map(|(w, h)| -> PyResult<(u16, u16)> {
            Ok((
                in_range("viewport width", w, 1, 2048)? as u16,
                in_range("viewport height", h, 1, 2048)? as u16,
            ))
        })
        .transpose()?;
    let load = LoadOpts {
        viewport,
        spp,
        ..LoadOpts::default()
    };
    let opts = RenderOpts {
        bounds,
        precision,
        progress: false,
    };
    let scene = scene.map(str::to_string);
    let r = py.detach(move || -> anyhow::Result<_> {
        let s = match scene.as_deref() {
            None => builtin::default_scene().with_opts(&load)?,
            Some(t) if t.trim_start().starts_with('{') => {
                Scene::parse_with(t, "scene", Path::new("."), &load)?.scene
            }
            Some(p) => Scene::load_with(Path::new(p), &load)?.scene,
        };
        let r = uvt_host::render::scene_render::render_with(&s, &opts)?;
        Ok((s.viewport, r.fixed.image, r.report))
    });
    let ((w, h), image, report) = r.map_err(|e| input_err(format!("{e:#}")))?;
    let flat: Vec<u8> = image.into_iter().flatten().collect();
    let a = numpy::ndarray::Array3::from_shape_vec((h as usize, w as usize, 3), flat)
        .map_err(|e| input_err(e.to_string()))?;
    let text = serde_json::to_string(&report).map_err(|e| input_err(e.to_string()))?;
    Ok((PyArray3::from_owned_array(py, a), text))
}

/// The native module `uvt._uvt` (the package `uvt` re-exports it).
#[pymodule]
fn _uvt(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("FORMAT_VERSION", uvt_records::format::FORMAT_VERSION)?;
    m.add("TRI_WORDS", TRI_WORDS)?;
    m.add("UvtError", py.get_type::<UvtError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("ConfigError", py.get_type::<ConfigError>())?;
    m.add_class::<Hit>()?;
    m.add_class::<Triangle>()?;
    for f in [
        wrap_pyfunction!(configs, m)?,
        wrap_pyfunction!(default_config, m)?,
        wrap_pyfunction!(strategies, m)?,
        wrap_pyfunction!(kinds, m)?,
        wrap_pyfunction!(fields, m)?,
        wrap_pyfunction!(gen, m)?,
        wrap_pyfunction!(shard_range, m)?,
        wrap_pyfunction!(stream_config, m)?,
        wrap_pyfunction!(run, m)?,
        wrap_pyfunction!(coverage, m)?,
        wrap_pyfunction!(coverage_bins, m)?,
        wrap_pyfunction!(compare, m)?,
        wrap_pyfunction!(decode, m)?,
        wrap_pyfunction!(render, m)?,
    ] {
        m.add_function(f)?;
    }
    Ok(())
}
