//! A second opinion by evaluation: the residual at random points in double-double.
