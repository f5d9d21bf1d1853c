//! What a function's parameters mean beyond their C types (array or scalar, input or output),
//! decided from the header's naming conventions; shared by the Fortran and C++ generators.

use crate::cheader::{Base, Func, Param};

/// Struct pointers are single objects (arrays only when plural and counted); numeric pointers
/// are arrays in functions that take a count (size_t) or read an input array (`const double *`),
/// otherwise `*_out` pointers are scalar outputs.
pub fn is_array_param(f: &Func, p: &Param) -> bool {
    if !p.ty.ptr || matches!(p.ty.base, Base::Char | Base::Void) {
        return false;
    }
    let counted = f
        .params
        .iter()
        .any(|q| q.ty.base == Base::Usize && !q.ty.ptr);
    if matches!(p.ty.base, Base::Named(_)) {
        return p.name.ends_with('s') && counted;
    }
    let reads_array = f.params.iter().any(|q| {
        q.ty.ptr && q.ty.is_const && !matches!(q.ty.base, Base::Named(_) | Base::Char | Base::Void)
    });
    counted || reads_array || !p.name.ends_with("_out")
}

pub fn is_pure(f: &Func) -> bool {
    // Functions that return a value and write through no pointer are pure in Fortran's sense.
    f.ret.base != Base::Void && !f.ret.ptr && f.params.iter().all(|p| !p.ty.ptr || p.ty.is_const)
}

/// Scalar status functions: by-value inputs (and const struct pointers) and one trailing scalar
/// `*_out`; these get an elemental wrapper.
pub fn scalar_out(f: &Func) -> Option<&Param> {
    if f.ret.base != Base::I32 || f.ret.ptr {
        return None;
    }
    let (last, rest) = f.params.split_last()?;
    let named_out = last.name == "out" || last.name.ends_with("_out");
    let ok_last = last.ty.ptr && !last.ty.is_const && named_out && !is_array_param(f, last);
    let ok_rest = rest
        .iter()
        .all(|p| !p.ty.ptr || (p.ty.is_const && matches!(p.ty.base, Base::Named(_))));
    let no_count = !f.params.iter().any(|p| p.ty.base == Base::Usize);
    (ok_last && ok_rest && no_count).then_some(last)
}
