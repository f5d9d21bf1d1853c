//! When a contact ends: two criteria, because host codes differ.

/// The event that ends a contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EndCriterion {
    /// The contact ends when the overlap δ returns to zero. The total force may turn attractive
    /// shortly before that; solvers that do not clamp the normal force realise this criterion.
    Overlap,
    /// The contact ends when the total normal force first reaches zero while unloading. Solvers
    /// that clamp attractive normal forces to zero (LIGGGHTS `limitForce`, LAMMPS
    /// `limit_damping`, Chrono, YADE) realise this criterion: after that instant no force acts
    /// and the particles separate at constant speed.
    Force,
}

impl EndCriterion {
    /// The C code of this criterion (`DC_END_OVERLAP` = 0, `DC_END_FORCE` = 1).
    pub const fn code(self) -> i32 {
        match self {
            EndCriterion::Overlap => 0,
            EndCriterion::Force => 1,
        }
    }

    /// The criterion for a C code, or `None` for an unknown code.
    pub const fn from_code(code: i32) -> Option<Self> {
        match code {
            0 => Some(EndCriterion::Overlap),
            1 => Some(EndCriterion::Force),
            _ => None,
        }
    }
}
