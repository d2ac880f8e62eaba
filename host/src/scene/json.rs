//! Strict JSON for scene files: duplicate keys are an error (serde_json's `Value` keeps the last
//! one silently), unknown keys are an error that suggests the nearest known key, and every integer
//! field is read by one function ([`integer`]), so `4` and `4.0` mean the same everywhere and
//! `4.5` is refused everywhere. Messages name the JSON path, e.g.
//! `meshes[2].sphere.segmnets: unknown key; did you mean "segments"?`. The value readers that
//! scene files and meshes share are here too: arrays of finite numbers ([`num_array`]) and
//! colors ([`color`]).

use std::fmt;

use anyhow::{anyhow, bail, Result};
use serde::de::{DeserializeSeed, Deserializer, Error as _, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Number, Value};

/// A JSON path built on the stack while parsing (only rendered when an error names it).
#[derive(Clone, Copy)]
enum Path<'a> {
    Root,
    Key(&'a Path<'a>, &'a str),
    Index(&'a Path<'a>, usize),
}

impl fmt::Display for Path<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Path::Root => Ok(()),
            Path::Key(Path::Root, k) => write!(f, "{k}"),
            Path::Key(p, k) => write!(f, "{p}.{k}"),
            Path::Index(p, i) => write!(f, "{p}[{i}]"),
        }
    }
}

struct Strict<'a>(Path<'a>);

impl<'de> DeserializeSeed<'de> for Strict<'_> {
    type Value = Value;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Strict<'_> {
    type Value = Value;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }
    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }
    fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Value, E> {
        Number::from_f64(v)
            .map(Value::Number)
            .ok_or_else(|| E::custom(format!("{}: {v} is not finite", self.0)))
    }
    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.into()))
    }
    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::new();
        while let Some(v) = seq.next_element_seed(Strict(Path::Index(&self.0, out.len())))? {
            out.push(v);
        }
        Ok(Value::Array(out))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(k) = map.next_key::<String>()? {
            if out.contains_key(&k) {
                let at = match self.0 {
                    Path::Root => "the scene".to_string(),
                    p => p.to_string(),
                };
                return Err(A::Error::custom(format!(
                    "{at}: duplicate key \"{k}\" (each key may appear once)"
                )));
            }
            let v = map.next_value_seed(Strict(Path::Key(&self.0, &k)))?;
            out.insert(k, v);
        }
        Ok(Value::Object(out))
    }
}

/// Parse JSON text, refusing duplicate keys. Syntax errors say "malformed JSON"; all errors carry
/// serde_json's line and column.
pub fn parse_strict(text: &str) -> Result<Value> {
    let mut de = serde_json::Deserializer::from_str(text);
    let v = Strict(Path::Root)
        .deserialize(&mut de)
        .and_then(|v| de.end().map(|()| v));
    v.map_err(|e| match e.classify() {
        serde_json::error::Category::Data => anyhow!("{e}"),
        _ => anyhow!("malformed JSON: {e}"),
    })
}

/// Levenshtein distance (for "did you mean").
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diag = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (diag + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diag = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The known key nearest to `key`, if it is plausibly a typo (distance ≤ max(2, len/3)).
pub fn nearest<'k>(key: &str, known: &[&'k str]) -> Option<&'k str> {
    let limit = (key.chars().count() / 3).max(2);
    known
        .iter()
        .map(|k| (distance(key, k), *k))
        .filter(|(d, _)| *d <= limit)
        .min()
        .map(|(_, k)| k)
}

/// `path` joined with `key` (`path` empty: the key alone).
pub fn join(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// `v` must be an object whose keys are all in `known`; returns it.
pub fn object<'v>(v: &'v Value, path: &str, known: &[&str]) -> Result<&'v Map<String, Value>> {
    let o = v.as_object().ok_or_else(|| {
        anyhow!(
            "{}: expected an object with keys {}, got {}",
            if path.is_empty() { "the scene" } else { path },
            known.join(", "),
            show(Some(v))
        )
    })?;
    for k in o.keys() {
        if !known.contains(&k.as_str()) {
            let hint = match nearest(k, known) {
                Some(n) => format!("did you mean \"{n}\"?"),
                None => format!("known keys: {}", known.join(", ")),
            };
            bail!("{}: unknown key; {hint}", join(path, k));
        }
    }
    Ok(o)
}

/// A whole number in `lo..=hi`, written as `4` or `4.0` alike (the one integer reader).
pub fn integer(v: &Value, path: &str, lo: u64, hi: u64) -> Result<u64> {
    let n = match v.as_u64() {
        Some(n) => Some(n),
        None => v
            .as_f64()
            .filter(|x| x.fract() == 0.0 && *x >= 0.0 && *x <= 9_007_199_254_740_992.0)
            .map(|x| x as u64),
    };
    match n {
        Some(n) if (lo..=hi).contains(&n) => Ok(n),
        _ => bail!(
            "{path}: {} is not a whole number in {lo}..={hi}",
            show(Some(v))
        ),
    }
}

/// A value for messages, shortened to 40 characters.
pub fn show(v: Option<&Value>) -> String {
    match v {
        None => "nothing".into(),
        Some(v) => {
            let s = v.to_string();
            match s.char_indices().nth(40) {
                Some((i, _)) => format!("{}…", &s[..i]),
                None => s,
            }
        }
    }
}

/// A JSON array of exactly `n` finite numbers.
pub fn num_array(v: &Value, n: usize, field: &str) -> Result<Vec<f64>> {
    let a = v.as_array().ok_or_else(|| {
        anyhow!(
            "{field}: expected an array of {n} numbers, got {}",
            show(Some(v))
        )
    })?;
    if a.len() != n {
        bail!("{field}: expected {n} numbers, got {}", a.len());
    }
    a.iter()
        .enumerate()
        .map(|(i, x)| {
            let f = x
                .as_f64()
                .ok_or_else(|| anyhow!("{field}[{i}]: {} is not a number", show(Some(x))))?;
            if !f.is_finite() {
                bail!("{field}[{i}]: {f} is not finite (NaN and infinity are refused)");
            }
            Ok(f)
        })
        .collect()
}

/// An RGB color: three whole numbers in 0..=255.
pub fn color(v: &Value, field: &str) -> Result<[u8; 3]> {
    let a = v
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(|| anyhow!("{field}: expected [r, g, b], got {}", show(Some(v))))?;
    let mut rgb = [0u8; 3];
    for (j, (x, d)) in a.iter().zip(rgb.iter_mut()).enumerate() {
        *d = integer(x, &format!("{field}[{j}]"), 0, 255)? as u8;
    }
    Ok(rgb)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicates_named_with_path() {
        let e = parse_strict(r#"{"a":{"b":[{"c":1,"c":2}]}}"#).unwrap_err();
        assert!(
            e.to_string().starts_with("a.b[0]: duplicate key \"c\""),
            "{e}"
        );
        let e = parse_strict(r#"{"spp":4,"spp":16}"#).unwrap_err();
        assert!(
            e.to_string().contains("the scene: duplicate key \"spp\""),
            "{e}"
        );
        let e = parse_strict(r#"{"a":1"#).unwrap_err();
        assert!(e.to_string().starts_with("malformed JSON"), "{e}");
        assert_eq!(
            parse_strict(r#"{"a":[1,2.5,"x",null,true]}"#).unwrap(),
            serde_json::json!({"a":[1,2.5,"x",null,true]})
        );
    }

    #[test]
    fn suggestions() {
        assert_eq!(nearest("sp", &["spp", "tile", "seed"]), Some("spp"));
        assert_eq!(nearest("colour", &["color", "t0"]), Some("color"));
        assert_eq!(
            nearest("segmnets", &["radius", "segments"]),
            Some("segments")
        );
        assert_eq!(nearest("zzzzzz", &["color", "t0"]), None);
        assert_eq!(distance("kitten", "sitting"), 3);
    }

    #[test]
    fn integers_alike() {
        let j = |s: &str| serde_json::from_str::<Value>(s).unwrap();
        assert_eq!(integer(&j("4"), "x", 1, 64).unwrap(), 4);
        assert_eq!(integer(&j("4.0"), "x", 1, 64).unwrap(), 4);
        assert_eq!(integer(&j("64"), "x", 1, 64).unwrap(), 64);
        for bad in ["4.5", "0", "65", "-1", "\"4\"", "null", "1e300"] {
            let e = integer(&j(bad), "spp", 1, 64).unwrap_err().to_string();
            assert!(e.starts_with("spp: ") && e.contains("1..=64"), "{bad}: {e}");
        }
        assert_eq!(
            integer(&j("18446744073709551615"), "s", 0, u64::MAX).unwrap(),
            u64::MAX
        );
    }
}
