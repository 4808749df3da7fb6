!----------------------------------------------------------------------
! rod: the Kirchhoff rod of Starostin & van der Heijden (2009) as an
! AUTO-07p boundary value problem, written for hockle's side-by-side
! timing (docs/PERFORMANCE.md). The same equations as hockle's rod
! (src/rod/problem.rs), scaled for AUTO's arclength norm: state
! U = (r, q, F/k^2, M/k), k = 2 pi n, B = 1, 13 components,
!   r' = d3 = R(q) e3,  q' = q (x) (0, u)/2,  F' = 0,  M' = F x d3,
!   u = D^-1 R^T M + u0,  D = diag(A, B=1, C),  u0 = 2 pi n (0, sin th0, cos th0).
! Boundary conditions: r(0) = 0, x(1) = y(1) = 0, F_z(0) = f (2 pi n)^2,
! M(0) = 0, M_x(1) = M_y(1) = 0, |q(0)|^2 = 1 (12); one integral: the
! rotational phase condition int <q, G q_old> ds = 0, G q = (k (x) q)/2.
! Parameters: PAR(1) = f = F_z/((2 pi n)^2 B), PAR(2) = th0 (rad),
! PAR(3) = A, PAR(4) = C, PAR(5) = n, PAR(6) = z(1) (output, by PVLS).
!----------------------------------------------------------------------
SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), IJAC
  DOUBLE PRECISION, INTENT(IN) :: U(NDIM), PAR(*)
  DOUBLE PRECISION, INTENT(OUT) :: F(NDIM)
  DOUBLE PRECISION, INTENT(INOUT) :: DFDU(NDIM,NDIM), DFDP(NDIM,*)
  DOUBLE PRECISION, PARAMETER :: PI = 3.14159265358979323846D0
  DOUBLE PRECISION w, x, y, z, R(3,3), mm(3), u1, u2, u3, k
  INTEGER i
  w = U(4); x = U(5); y = U(6); z = U(7)
  R(1,1) = w*w + x*x - y*y - z*z; R(1,2) = 2*(x*y - w*z); R(1,3) = 2*(x*z + w*y)
  R(2,1) = 2*(x*y + w*z); R(2,2) = w*w - x*x + y*y - z*z; R(2,3) = 2*(y*z - w*x)
  R(3,1) = 2*(x*z - w*y); R(3,2) = 2*(y*z + w*x); R(3,3) = w*w - x*x - y*y + z*z
  DO i = 1, 3
     mm(i) = R(1,i)*U(11) + R(2,i)*U(12) + R(3,i)*U(13)
  END DO
  k = 2*PI*PAR(5)
  u1 = k*mm(1)/PAR(3)
  u2 = k*(mm(2) + SIN(PAR(2)))
  u3 = k*(mm(3)/PAR(4) + COS(PAR(2)))
  F(1) = R(1,3); F(2) = R(2,3); F(3) = R(3,3)
  F(4) = -0.5D0*(x*u1 + y*u2 + z*u3)
  F(5) = 0.5D0*(w*u1 + y*u3 - z*u2)
  F(6) = 0.5D0*(w*u2 + z*u1 - x*u3)
  F(7) = 0.5D0*(w*u3 + x*u2 - y*u1)
  F(8) = 0; F(9) = 0; F(10) = 0
  F(11) = k*(U(9)*R(3,3) - U(10)*R(2,3))
  F(12) = k*(U(10)*R(1,3) - U(8)*R(3,3))
  F(13) = k*(U(8)*R(2,3) - U(9)*R(1,3))
END SUBROUTINE FUNC

SUBROUTINE STPNT(NDIM,U,PAR,T)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM
  DOUBLE PRECISION, INTENT(INOUT) :: U(NDIM), PAR(*)
  DOUBLE PRECISION, INTENT(IN) :: T
  DOUBLE PRECISION, PARAMETER :: PI = 3.14159265358979323846D0
  DOUBLE PRECISION n, th, phi, r0, b, a
  ! the paper's spring: theta0 = 89.8 deg, A/B = 10, C/B = 2 A/(B (1 + nu)(1 + A/B)), nu = 0.05, n = 4
  PAR(2) = 89.8D0*PI/180
  PAR(3) = 10.0D0
  PAR(4) = 2*10.0D0/(1.05D0*11.0D0)
  PAR(5) = 4.0D0
  PAR(1) = 0
  n = PAR(5); th = PAR(2)
  phi = 2*PI*n*T
  r0 = SIN(th)/(2*PI*n)
  b = (phi + PI/2)/2
  a = th/2
  U(1) = r0*SIN(phi); U(2) = r0*(1 - COS(phi)); U(3) = COS(th)*T
  U(4) = COS(b)*COS(a); U(5) = COS(b)*SIN(a); U(6) = SIN(b)*SIN(a); U(7) = SIN(b)*COS(a)
  U(8:13) = 0
  PAR(6) = COS(th)
END SUBROUTINE STPNT

SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), NBC, IJAC
  DOUBLE PRECISION, INTENT(IN) :: PAR(*), U0(NDIM), U1(NDIM)
  DOUBLE PRECISION, INTENT(OUT) :: FB(NBC)
  DOUBLE PRECISION, INTENT(INOUT) :: DBC(NBC,*)
  DOUBLE PRECISION, PARAMETER :: PI = 3.14159265358979323846D0
  FB(1) = U0(1); FB(2) = U0(2); FB(3) = U0(3)
  FB(4) = U1(1); FB(5) = U1(2)
  FB(6) = U0(10) - PAR(1)
  FB(7) = U0(11); FB(8) = U0(12); FB(9) = U0(13)
  FB(10) = U1(11); FB(11) = U1(12)
  FB(12) = 0.5D0*(U0(4)**2 + U0(5)**2 + U0(6)**2 + U0(7)**2 - 1)
END SUBROUTINE BCND

SUBROUTINE ICND(NDIM,PAR,ICP,NINT,U,UOLD,UDOT,UPOLD,FI,IJAC,DINT)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), NINT, IJAC
  DOUBLE PRECISION, INTENT(IN) :: PAR(*)
  DOUBLE PRECISION, INTENT(IN) :: U(NDIM), UOLD(NDIM), UDOT(NDIM), UPOLD(NDIM)
  DOUBLE PRECISION, INTENT(OUT) :: FI(NINT)
  DOUBLE PRECISION, INTENT(INOUT) :: DINT(NINT,*)
  FI(1) = 0.5D0*(-U(4)*UOLD(7) - U(5)*UOLD(6) + U(6)*UOLD(5) + U(7)*UOLD(4))
END SUBROUTINE ICND

SUBROUTINE FOPT
END SUBROUTINE FOPT

SUBROUTINE PVLS(NDIM,U,PAR)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM
  DOUBLE PRECISION, INTENT(IN) :: U(NDIM)
  DOUBLE PRECISION, INTENT(INOUT) :: PAR(*)
  DOUBLE PRECISION GETP
  PAR(6) = GETP('BV1', 3, U)
END SUBROUTINE PVLS
