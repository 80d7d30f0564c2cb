//! One table of names per fieldless enum of this crate ([`crate::SegmentKind`],
//! [`crate::method::Method`]): `ALL`, `name()`, `Display` and the lookup their `FromStr` impls
//! share.

/// Implements `ALL`, `name()` (with a doc example), `Display` and a crate-private `from_name`
/// for a fieldless enum from one `Variant => "name"` table.
macro_rules! named {
    ($path:literal, $ty:ident { $($variant:ident => $name:literal),* $(,)? }) => {
        impl $ty {
            /// Every variant, in the table's order (for tests and tools that cover them all).
            ///
            /// ```
            #[doc = concat!("use ", $path, ";")]
            #[doc = concat!("for v in ", stringify!($ty), "::ALL {")]
            ///     assert_eq!(v.name().parse(), Ok(v));
            /// }
            /// ```
            pub const ALL: [$ty; [$(stringify!($variant)),*].len()] = [$($ty::$variant),*];

            /// The name (as parsed by `FromStr` and printed by `Display`).
            ///
            /// ```
            #[doc = concat!("use ", $path, ";")]
            #[doc = concat!("for v in [", $("", stringify!($ty), "::", stringify!($variant), ", ",)* "] {")]
            ///     assert_eq!(v.name().parse(), Ok(v));
            ///     assert_eq!(v.to_string(), v.name());
            /// }
            /// ```
            pub fn name(self) -> &'static str {
                match self {
                    $($ty::$variant => $name),*
                }
            }

            /// The variant called `s`, if any.
            pub(crate) fn from_name(s: &str) -> Option<Self> {
                Self::ALL.into_iter().find(|v| v.name() == s)
            }
        }

        impl std::fmt::Display for $ty {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }
    };
}

pub(crate) use named;
