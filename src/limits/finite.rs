//! Finds a non-finite number anywhere in a serialisable value (a build
//! report, a document), with the path of the field that holds it:
//! `profile_error[0].max_rel`. JSON writes NaN as `null`, so a report
//! must be checked before it is printed.

use serde::ser::{self, Serialize};

/// A non-finite number found at `path`.
#[derive(Debug, Clone, PartialEq)]
pub struct NonFinite {
    pub path: String,
    pub value: f64,
}

/// The first non-finite `f64`/`f32` in `v` (depth first, fields in
/// declaration order), or `None`.
pub fn first_non_finite<T: Serialize + ?Sized>(v: &T) -> Option<NonFinite> {
    let mut w = Walker {
        path: Vec::new(),
        found: None,
    };
    let _ = v.serialize(&mut w);
    w.found
}

struct Walker {
    path: Vec<String>,
    found: Option<NonFinite>,
}

/// Stops the walk at the first find (or never: the walk cannot fail).
#[derive(Debug)]
struct Stop;

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("stop")
    }
}
impl std::error::Error for Stop {}
impl ser::Error for Stop {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        Stop
    }
}

impl Walker {
    fn float(&mut self, v: f64) -> Result<(), Stop> {
        if v.is_finite() {
            return Ok(());
        }
        let mut path = String::new();
        for p in &self.path {
            if p.starts_with('[') || path.is_empty() {
                path.push_str(p);
            } else {
                path.push('.');
                path.push_str(p);
            }
        }
        self.found = Some(NonFinite { path, value: v });
        Err(Stop)
    }
    fn enter<T: Serialize + ?Sized>(&mut self, key: String, v: &T) -> Result<(), Stop> {
        self.path.push(key);
        let r = v.serialize(&mut *self);
        self.path.pop();
        r
    }
}

/// Sequence, tuple, map and struct walker (counts elements for paths).
struct Compound<'a> {
    w: &'a mut Walker,
    index: usize,
    /// A variant name was pushed on the path (popped at the end).
    pushed: bool,
}

macro_rules! ok_scalars {
    ($($f:ident: $t:ty),*) => {
        $(fn $f(self, _: $t) -> Result<(), Stop> { Ok(()) })*
    };
}

impl<'a> ser::Serializer for &'a mut Walker {
    type Ok = ();
    type Error = Stop;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    ok_scalars!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str, serialize_bytes: &[u8]);

    fn serialize_f32(self, v: f32) -> Result<(), Stop> {
        self.float(v as f64)
    }
    fn serialize_f64(self, v: f64) -> Result<(), Stop> {
        self.float(v)
    }
    fn serialize_none(self) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> Result<(), Stop> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Stop> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        v: &T,
    ) -> Result<(), Stop> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        v: &T,
    ) -> Result<(), Stop> {
        self.enter(variant.to_string(), v)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, None))
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, None))
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, None))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, Some(variant)))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, None))
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, None))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Stop> {
        Ok(Compound::new(self, Some(variant)))
    }
}

impl<'a> Compound<'a> {
    fn new(w: &'a mut Walker, variant: Option<&str>) -> Compound<'a> {
        if let Some(v) = variant {
            w.path.push(v.to_string());
        }
        Compound {
            w,
            index: 0,
            pushed: variant.is_some(),
        }
    }
    fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Stop> {
        let k = format!("[{}]", self.index);
        self.index += 1;
        self.w.enter(k, v)
    }
    fn field<T: Serialize + ?Sized>(&mut self, name: &str, v: &T) -> Result<(), Stop> {
        self.w.enter(name.to_string(), v)
    }
    fn done(self) -> Result<(), Stop> {
        if self.pushed {
            self.w.path.pop();
        }
        Ok(())
    }
}

/// The sequence-like compounds: each element is the next index.
macro_rules! indexed_compound {
    ($($trait:ident :: $method:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Stop;
            fn $method<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Stop> {
                self.element(v)
            }
            fn end(self) -> Result<(), Stop> {
                self.done()
            }
        }
    )*};
}
indexed_compound!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);
impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Stop;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, k: &T) -> Result<(), Stop> {
        // keys are names (strings) in every report; numbers are shown as found
        let name = serde_json::to_value(k)
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_else(|| format!("[{}]", self.index));
        self.index += 1;
        self.w.path.push(name);
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Stop> {
        let r = v.serialize(&mut *self.w);
        self.w.path.pop();
        r
    }
    fn end(self) -> Result<(), Stop> {
        self.done()
    }
}
/// The struct-like compounds: each field is its name.
macro_rules! named_compound {
    ($($trait:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Stop;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                k: &'static str,
                v: &T,
            ) -> Result<(), Stop> {
                self.field(k, v)
            }
            fn end(self) -> Result<(), Stop> {
                self.done()
            }
        }
    )*};
}
named_compound!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Serialize)]
    struct Row {
        view: String,
        max_rel: f64,
    }
    #[derive(serde::Serialize)]
    struct Report {
        ok: bool,
        rows: Vec<Row>,
        extra: Option<[f32; 2]>,
    }

    #[test]
    fn the_path_of_the_first_non_finite_number_is_named() {
        let mut r = Report {
            ok: true,
            rows: vec![
                Row {
                    view: "front".into(),
                    max_rel: 0.1,
                },
                Row {
                    view: "side".into(),
                    max_rel: f64::NAN,
                },
            ],
            extra: None,
        };
        let f = first_non_finite(&r).expect("found");
        assert_eq!(f.path, "rows[1].max_rel");
        assert!(f.value.is_nan());
        r.rows[1].max_rel = 0.2;
        assert_eq!(first_non_finite(&r), None);
        r.extra = Some([1.0, f32::INFINITY]);
        assert_eq!(first_non_finite(&r).expect("found").path, "extra[1]");
    }
}
