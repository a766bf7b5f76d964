//! Dimensions of a claim: every written term of both sides in one dimension.
