//! Principal axes of inertia of a numeric inertia tensor.
//!
//! In the chapter's convention the tensor is
//! `[I] = [[I_x, -I_xy, -I_xz], [-I_xy, I_y, -I_yz], [-I_xz, -I_yz, I_z]]`
//! (products of inertia are the positive integrals `I_xy = ∫xy dm`). Being symmetric, it has
//! an orthonormal eigenbasis: `[I] = R diag(I_x', I_y', I_z') Rᵀ`, where the columns of `R`
//! are the principal axes written in the original frame and `I_x' <= I_y' <= I_z'` are the
//! principal moments. In the principal frame `H_x' = I_x' ω_x'` and so on.
//!
//! Method:
//! 1. A tensor that is already diagonal is answered in closed form: its diagonal, sorted,
//!    and a signed permutation of the coordinate axes (the identity when the diagonal is
//!    already ascending).
//! 2. Otherwise nalgebra's [`SymmetricEigen`] gives the three eigenvalues (always
//!    well conditioned). Its eigenvectors are not used directly, because the two axes of a
//!    nearly equal pair of moments are ill conditioned and would drag the third one with
//!    them. Instead the *most isolated* eigenvalue `λ` is taken, and its axis is the null
//!    vector of `[I] - λ 1`, the largest cross product of two of its rows; its error is
//!    round-off divided by the gap to the other two moments, which is the largest gap there
//!    is. The remaining pair is found by a closed-form 2×2 Jacobi rotation in the plane
//!    orthogonal to that axis, so the frame is orthonormal to round-off whatever the gap.
//!    The moments are the Rayleigh quotients `eᵀ [I] e` of the final axes.
//! 3. The axes are ordered by ascending moment, and the last one is reversed if needed so
//!    that `det R = +1` (a proper rotation).
//!
//! For an axisymmetric tensor (two equal moments, in any orientation) the distinct moment is
//! the isolated one, so its axis, the symmetry axis, is exact to round-off; the two equal
//! moments get an arbitrary orthonormal pair of axes orthogonal to it.

use super::validation::{validate_inertia_tensor, PhysicsError};
use nalgebra::{Matrix3, Rotation3, SymmetricEigen, Vector3};

/// Principal moments and axes: `tensor = rotation · diag(moments) · rotationᵀ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalAxes {
    /// Principal moments of inertia `(I_x', I_y', I_z')`, in ascending order.
    pub moments: Vector3<f64>,
    /// Proper rotation whose columns are the principal axes `x', y', z'` written in the
    /// frame of the given tensor: it maps principal-frame components to original ones.
    pub rotation: Rotation3<f64>,
}

/// Principal moments (ascending) and axes (a proper rotation) of an inertia tensor in the
/// chapter's convention. The tensor is first checked with [`validate_inertia_tensor`].
///
/// ```
/// use kinetics::mechanics::principal_axes::principal_axes;
/// use nalgebra::Matrix3;
/// // I_x = I_y = 2, I_xy = 1: principal moments 1 and 3 along the diagonals of the xy plane.
/// let tensor = Matrix3::new(2.0, -1.0, 0.0, -1.0, 2.0, 0.0, 0.0, 0.0, 2.5);
/// let axes = principal_axes(&tensor).unwrap();
/// assert!((axes.moments - nalgebra::Vector3::new(1.0, 2.5, 3.0)).amax() < 1e-14);
/// let rebuilt = axes.rotation.matrix()
///     * Matrix3::from_diagonal(&axes.moments)
///     * axes.rotation.matrix().transpose();
/// assert!((rebuilt - tensor).amax() < 1e-14);
/// ```
pub fn principal_axes(tensor: &Matrix3<f64>) -> Result<PrincipalAxes, PhysicsError> {
    validate_inertia_tensor(tensor)?;
    // Validation accepts an asymmetry below its tolerance; work on the symmetric part.
    let symmetric = (tensor + tensor.transpose()) * 0.5;
    let pairs = if is_diagonal(&symmetric) {
        [0, 1, 2].map(|k| (symmetric[(k, k)], Vector3::ith(k, 1.0)))
    } else {
        eigen_pairs(&symmetric)
    };
    Ok(proper_ascending_frame(pairs))
}

fn is_diagonal(tensor: &Matrix3<f64>) -> bool {
    (0..3).all(|r| (0..3).all(|c| r == c || tensor[(r, c)] == 0.0))
}

/// Eigenpairs of a symmetric, non-diagonal tensor with an orthonormal set of axes.
fn eigen_pairs(tensor: &Matrix3<f64>) -> [(f64, Vector3<f64>); 3] {
    let eigen = SymmetricEigen::new(*tensor);
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
    let [low, mid, high] = order.map(|k| eigen.eigenvalues[k]);
    // The eigenvalue farther from its neighbour is the isolated one.
    let isolated = if mid - low > high - mid {
        order[0]
    } else {
        order[2]
    };
    let lambda = eigen.eigenvalues[isolated];
    let axis = null_vector(&(tensor - Matrix3::from_diagonal_element(lambda)))
        .unwrap_or_else(|| eigen.eigenvectors.column(isolated).normalize());
    let (u, w) = orthonormal_complement(&axis);
    let (p, r) = diagonalise_in_plane(tensor, &u, &w);
    [axis, p, r].map(|e| (rayleigh_quotient(tensor, &e), e))
}

/// Unit vector spanning the null space of a rank-2 matrix: the largest cross product of two
/// of its rows. `None` when every cross product vanishes (all moments equal).
fn null_vector(matrix: &Matrix3<f64>) -> Option<Vector3<f64>> {
    let rows = [0, 1, 2].map(|k| matrix.row(k).transpose());
    [(0, 1), (0, 2), (1, 2)]
        .map(|(a, b)| rows[a].cross(&rows[b]))
        .into_iter()
        .max_by(|a, b| a.norm_squared().total_cmp(&b.norm_squared()))
        .filter(|v| v.norm_squared() > 0.0)
        .map(|v| v.normalize())
}

/// Two unit vectors `u, w` such that `(axis, u, w)` is a right-handed orthonormal triad.
pub(super) fn orthonormal_complement(axis: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let least_aligned = axis.iamin();
    let u = axis.cross(&Vector3::ith(least_aligned, 1.0)).normalize();
    let w = axis.cross(&u);
    (u, w)
}

/// Rotates `u, w` within their plane so that they diagonalise the restriction of the tensor
/// to that plane: the Jacobi angle `tan 2θ = 2 uᵀIw / (uᵀIu - wᵀIw)`.
fn diagonalise_in_plane(
    tensor: &Matrix3<f64>,
    u: &Vector3<f64>,
    w: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let a = rayleigh_quotient(tensor, u);
    let c = rayleigh_quotient(tensor, w);
    let b = u.dot(&(tensor * w));
    let theta = 0.5 * (2.0 * b).atan2(a - c);
    let (sin, cos) = theta.sin_cos();
    (u * cos + w * sin, w * cos - u * sin)
}

fn rayleigh_quotient(tensor: &Matrix3<f64>, unit: &Vector3<f64>) -> f64 {
    unit.dot(&(tensor * unit))
}

/// Sorts the pairs by ascending moment and makes the frame right-handed.
fn proper_ascending_frame(mut pairs: [(f64, Vector3<f64>); 3]) -> PrincipalAxes {
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut matrix = Matrix3::from_columns(&pairs.map(|(_, axis)| axis));
    if matrix.determinant() < 0.0 {
        matrix.set_column(2, &(-matrix.column(2)));
    }
    PrincipalAxes {
        moments: Vector3::from(pairs.map(|(moment, _)| moment)),
        rotation: Rotation3::from_matrix_unchecked(matrix),
    }
}
