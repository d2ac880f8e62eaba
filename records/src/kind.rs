//! The record kinds by name (the stages of [`STAGES`]) and one entry point per operation that
//! every consumer calls: [`run`] (input record → the core → output record), [`complete`] (fill an
//! input record's derived fields), [`diff`] (compare two output records field by field, all fields
//! or the architectural ones only). `uvt vectors check`, `ver`, `decode` and the C library go
//! through here, so they cannot disagree on what a record means.

use crate::format::{field_value, layout, show_field, Rec, SETUP_ARCHITECTURAL, STAGES};

use crate::{bsample, psample, stages};

/// One of the seven record kinds (a stage's `*_in` / `*_out` pair).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// triangle setup (`setup_in` → `setup_out`) at the record's configuration
    Setup,
    /// per-tile bounds of Laine 2011 (`bounds_in` names a `setup_in` record)
    Bounds,
    /// the per-sample interval check
    Select,
    /// the exact sample test (`sample_in` names a `setup_in` record of an exact configuration)
    Sample,
    /// the bounded sample test (self-contained; any bounded configuration)
    Bsample,
    /// the planar static sample test (self-contained; the planar configuration)
    Psample,
    /// the pixel resolve (one word per sample)
    Resolve,
}

/// Largest samples per pixel of a resolve record.
pub const MAX_SPP: u32 = 64;

impl Kind {
    /// Every kind, in the order of [`STAGES`] (the C library's `UVT_KIND_*` codes are the index).
    pub const ALL: [Kind; 7] = [
        Kind::Setup,
        Kind::Bounds,
        Kind::Select,
        Kind::Sample,
        Kind::Bsample,
        Kind::Psample,
        Kind::Resolve,
    ];
    /// The stage name (`setup`, …, `resolve`): the file stem without `_in` / `_out`.
    pub fn name(self) -> &'static str {
        STAGES[self.code() as usize]
    }
    /// The kind's code (its index in [`Kind::ALL`]).
    pub fn code(self) -> u32 {
        match self {
            Kind::Setup => 0,
            Kind::Bounds => 1,
            Kind::Select => 2,
            Kind::Sample => 3,
            Kind::Bsample => 4,
            Kind::Psample => 5,
            Kind::Resolve => 6,
        }
    }
    /// The kind of code `c`.
    pub fn from_code(c: u32) -> Option<Kind> {
        Kind::ALL.get(usize::try_from(c).ok()?).copied()
    }
    /// The kind named `s`; the error lists the names.
    pub fn parse(s: &str) -> Result<Kind, String> {
        Kind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("unknown record kind `{s}` (one of {})", STAGES.join(", ")))
    }
    /// Words of an input record (`spp` samples for a resolve record): the layout's, kept as
    /// constants for the per-record paths (`records/tests/codec/layout.rs` holds them equal to [`layout`]).
    pub fn words_in(self, spp: u32) -> u32 {
        match self {
            Kind::Setup => 32,
            Kind::Bounds => 3,
            Kind::Select => 9,
            Kind::Sample => 6,
            Kind::Bsample => 37,
            Kind::Psample => 28,
            Kind::Resolve => spp,
        }
    }
    /// Words of an output record (the layout's, as [`Kind::words_in`]).
    pub fn words_out(self) -> u32 {
        match self {
            Kind::Setup => 108,
            Kind::Bounds => 7,
            Kind::Select | Kind::Resolve => 1,
            Kind::Sample => 26,
            Kind::Bsample => 14,
            Kind::Psample => 8,
        }
    }
    /// Whether an input record names its triangle by index in a `setup_in` file (bounds and the
    /// exact sample test): [`run`] then takes that `setup_in` record beside it.
    pub fn needs_setup(self) -> bool {
        matches!(self, Kind::Bounds | Kind::Sample)
    }
    /// The output fields a unit must produce (what `--arch-only` checks): setup's
    /// [`SETUP_ARCHITECTURAL`] (not the Laine coefficients), the coverage and depth of the sample
    /// tests and the inside bit of the interval check; every field otherwise.
    pub fn architectural(self) -> Option<&'static [&'static str]> {
        match self {
            Kind::Setup => Some(&SETUP_ARCHITECTURAL),
            Kind::Sample | Kind::Bsample | Kind::Psample => Some(&["covered", "depth"]),
            Kind::Select => Some(&["inside"]),
            _ => None,
        }
    }
}

/// Samples per pixel of a resolve record of `words` words; an error outside 1..=[`MAX_SPP`].
pub fn resolve_spp(words: usize) -> Result<u32, String> {
    match u32::try_from(words) {
        Ok(n) if (1..=MAX_SPP).contains(&n) => Ok(n),
        _ => Err(format!(
            "a resolve record has 1..={MAX_SPP} words (one per sample), not {words}"
        )),
    }
}

fn check_len(kind: Kind, file: &str, words: usize, want: u32) -> Result<(), String> {
    if words == want as usize {
        Ok(())
    } else {
        Err(format!(
            "the {}{file} record has {words} words, the layout has {want} (format version {})",
            kind.name(),
            crate::format::FORMAT_VERSION
        ))
    }
}

/// Run the core on input record `input` of `kind` and return the expected output record.
/// `setup_in` is the `setup_in` record a bounds or exact sample-test record names (its `tri`
/// field is ignored then: the record given is the triangle). Every field is validated through the
/// core's checked constructors; an error names the field.
pub fn run(kind: Kind, input: &[u32], setup_in: Option<&[u32]>) -> Result<Rec, String> {
    let spp = if kind == Kind::Resolve {
        resolve_spp(input.len())?
    } else {
        0
    };
    check_len(kind, "_in", input.len(), kind.words_in(spp))?;
    let setup = || -> Result<_, String> {
        let s = setup_in.ok_or_else(|| {
            format!(
                "a {}_in record names its triangle in setup_in: give that setup_in record too",
                kind.name()
            )
        })?;
        check_len(Kind::Setup, "_in", s.len(), Kind::Setup.words_in(0))?;
        stages::run_setup(s)?.0.ok_or_else(|| {
            "the setup_in record's triangle is culled: it has no bounds or sample records"
                .to_string()
        })
    };
    Ok(match kind {
        Kind::Setup => stages::run_setup(input)?.1,
        Kind::Bounds => {
            let s = setup()?;
            stages::run_bounds(&|_| Ok(s), input)?.1
        }
        Kind::Select => stages::run_select(input)?,
        Kind::Sample => {
            let s = setup()?;
            stages::run_sample(&|_| Ok(s), input)?.1
        }
        Kind::Bsample => bsample::run_bsample(input)?.1,
        Kind::Psample => {
            let (core_in, _, out) = psample::run_psample(input)?;
            if let Some(m) = first_difference("psample_in", &core_in.0, input, None) {
                return Err(format!(
                    "the record's planar setup fields are not the core's: {m} (uvt_complete / `uvt vectors gen` fill them)"
                ));
            }
            out
        }
        Kind::Resolve => stages::run_resolve(input),
    })
}

/// Fill the fields of input record `input` that follow from its other fields: a bounded record's
/// `class` (from its triangle) and a planar record's setup fields (edge normals, σ, depth
/// plane, from its vertices). Other kinds have none (their record is returned unchanged).
pub fn complete(kind: Kind, input: &mut [u32]) -> Result<(), String> {
    check_len(kind, "_in", input.len(), kind.words_in(input.len() as u32))?;
    match kind {
        Kind::Bsample => {
            let class = bsample::triangle_class(input)?;
            input[31] = (input[31] & !3) | class;
        }
        Kind::Psample => {
            let (core_in, _, _) = psample::run_psample(input)?;
            input.copy_from_slice(&core_in.0);
        }
        _ => {}
    }
    Ok(())
}

/// The first field of `file` (e.g. `bsample_out`) whose value differs between `expected` and
/// `observed`, as "field NAME: expected … observed …"; `only` restricts the comparison to the
/// named fields. `None` when they agree.
pub fn first_difference(
    file: &str,
    expected: &[u32],
    observed: &[u32],
    only: Option<&[&str]>,
) -> Option<String> {
    diff(file, expected, observed, only).into_iter().next()
}

/// One field two records differ in ([`diff_fields`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldDiff {
    /// the field (its name, words and bits: [`field_value`] reads it from either record)
    pub field: crate::format::RecField,
    /// "field NAME: expected HEX = DECODED, observed HEX = DECODED"
    pub message: String,
}

/// Every field of `file` whose value differs between `expected` and `observed`, in layout order;
/// `only` restricts the comparison to the named fields.
pub fn diff_fields(
    file: &str,
    expected: &[u32],
    observed: &[u32],
    only: Option<&[&str]>,
) -> Vec<FieldDiff> {
    if expected == observed {
        return Vec::new(); // the common case, without building the layout
    }
    let spp = expected.len().max(observed.len()) as u32;
    layout(file, spp)
        .fields
        .into_iter()
        .filter(|f| only.map_or(true, |o| o.contains(&f.name.as_str())))
        .filter(|f| field_value(f, expected) != field_value(f, observed))
        .map(|f| {
            let (a, b) = (show_field(&f, expected), show_field(&f, observed));
            FieldDiff {
                message: format!("field {}: expected {a}, observed {b}", f.name),
                field: f,
            }
        })
        .collect()
}

/// Every field of `file` whose value differs, one message per field ("field NAME: expected HEX =
/// DECODED, observed HEX = DECODED"); `only` restricts the comparison to the named fields.
pub fn diff(file: &str, expected: &[u32], observed: &[u32], only: Option<&[&str]>) -> Vec<String> {
    diff_fields(file, expected, observed, only)
        .into_iter()
        .map(|d| d.message)
        .collect()
}

/// Every field of `file`'s record `words`, one line each ("NAME = HEX = DECODED").
pub fn decode(file: &str, words: &[u32]) -> Vec<String> {
    layout(file, words.len() as u32)
        .fields
        .iter()
        .map(|f| format!("{} = {}", f.name, show_field(f, words)))
        .collect()
}
