//! Products of expression vectors and matrices, each component one sum of products:
//!
//! ```text
//! ([M]{v})ᵢ = Σⱼ Mᵢⱼ vⱼ,    a · b = Σᵢ aᵢ bᵢ,    (a × b)ᵢ = aⱼ bₖ − aₖ bⱼ  (i, j, k cyclic)
//! ```
//!
//! They equal nalgebra's `m * v`, `a.dot(&b)` and `a.cross(&b)` on `Matrix3<Expr>` and
//! `Vector3<Expr>`, which build every component from binary operations (a clone, a product
//! and a partial sum per entry); these build each component with
//! [`Expr::sum_of_products`] instead.
//!
//! ```
//! use kinetics::algebra::{vector_products, Expr, Matrix, Vector};
//! let s = Expr::symbol;
//! let m = Matrix::from_fn(|i, j| s(&format!("m_{i}{j}")));
//! let (v, w) = (Vector::new(s("x"), s("y"), s("z")), Vector::new(s("a"), s("b"), s("c")));
//! assert_eq!(vector_products::mat_vec(&m, &v), &m * &v);
//! assert_eq!(vector_products::dot(&v, &w), v.dot(&w));
//! assert_eq!(vector_products::cross(&v, &w), v.cross(&w));
//! ```

use super::{Expr, Matrix, Vector};

/// `[M]{v}`.
pub fn mat_vec(m: &Matrix, v: &Vector) -> Vector {
    Vector::from_fn(|i, _| {
        Expr::sum_of_products(&[
            (&m[(i, 0)], &v[0]),
            (&m[(i, 1)], &v[1]),
            (&m[(i, 2)], &v[2]),
        ])
    })
}

/// `a · b`.
pub fn dot(a: &Vector, b: &Vector) -> Expr {
    Expr::sum_of_products(&[(&a[0], &b[0]), (&a[1], &b[1]), (&a[2], &b[2])])
}

/// `a × b`.
pub fn cross(a: &Vector, b: &Vector) -> Vector {
    Vector::from_fn(|i, _| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Expr::difference_of_products((&a[j], &b[k]), (&a[k], &b[j]))
    })
}
