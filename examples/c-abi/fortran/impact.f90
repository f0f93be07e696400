! One Kharaz impact at 20 degrees (talk's parameters, Model AA, dt = t_c/50) through the
! soft-sphere C ABI from Fortran, with iso_c_binding. Prints "angle e_t".
module soft_sphere
  use iso_c_binding
  implicit none
  integer(c_int32_t), parameter :: SS_OK = 0, SS_MODEL_AA = 1
  type, bind(c) :: ss_vec3_f64
    real(c_double) :: x, y, z
  end type
  type, bind(c) :: ss_sphere_f64
    type(ss_vec3_f64) :: position, velocity, angular_velocity
    real(c_double) :: radius, mass
  end type
  type, bind(c) :: ss_wall_f64
    type(ss_vec3_f64) :: point, normal, velocity
  end type
  type, bind(c) :: ss_params_f64
    integer(c_int32_t) :: model
    real(c_double) :: normal_stiffness, restitution, tangential_stiffness, dashpot_ratio, &
                      friction, time_step, smallest_effective_mass, effective_modulus, &
                      effective_shear_modulus, largest_impact_speed, largest_effective_radius
  end type
  type, bind(c) :: ss_state_f64
    type(ss_vec3_f64) :: displacement, spring_force
    real(c_double) :: contact_radius
  end type
  type, bind(c) :: ss_forces_f64
    integer(c_int32_t) :: touching, sliding
    real(c_double) :: overlap, normal_force
    type(ss_vec3_f64) :: force_on_j, torque_on_i, torque_on_j
  end type
  interface
    integer(c_int32_t) function ss_contact_duration_f64(params, m_star, out) bind(c)
      import
      type(ss_params_f64), intent(in) :: params
      real(c_double), value :: m_star
      real(c_double), intent(out) :: out
    end function
    integer(c_int32_t) function ss_law_new_f64(params, law) bind(c)
      import
      type(ss_params_f64), intent(in) :: params
      type(c_ptr), intent(out) :: law
    end function
    subroutine ss_law_free_f64(law) bind(c)
      import
      type(c_ptr), value :: law
    end subroutine
    integer(c_int32_t) function ss_sphere_wall_f64(law, sphere, wall, state, out) bind(c)
      import
      type(c_ptr), value :: law
      type(ss_sphere_f64), intent(in) :: sphere
      type(ss_wall_f64), intent(in) :: wall
      type(ss_state_f64), intent(inout) :: state
      type(ss_forces_f64), intent(out) :: out
    end function
    integer(c_int32_t) function ss_advance_sphere_f64(law, sphere, force, torque) bind(c)
      import
      type(c_ptr), value :: law
      type(ss_sphere_f64), intent(inout) :: sphere
      type(ss_vec3_f64), value :: force, torque
    end function
  end interface
end module

program impact
  use soft_sphere
  implicit none
  real(c_double), parameter :: pi = 3.14159265358979323846d0
  real(c_double), parameter :: radius = 2.5d-3, density = 2700d0, speed = 3.9d0
  integer, parameter :: angle = 20
  type(ss_params_f64) :: params
  type(ss_sphere_f64) :: sphere
  type(ss_wall_f64) :: floor_wall
  type(ss_state_f64) :: state
  type(ss_forces_f64) :: f
  type(ss_vec3_f64) :: zero
  type(c_ptr) :: law
  real(c_double) :: mass, duration, theta, incoming
  logical :: touched
  integer(c_int32_t) :: code

  mass = (4d0 / 3d0) * pi * radius * radius * radius * density
  params = ss_params_f64(SS_MODEL_AA, 1000d0, 0.98d0, 860d0, 0d0, 0.092d0, 0d0, mass, &
                         0d0, 0d0, 0d0, 0d0)
  code = ss_contact_duration_f64(params, mass, duration)
  params%time_step = duration / 50d0
  code = ss_law_new_f64(params, law)
  if (code /= SS_OK) stop 1
  theta = angle * (pi / 180d0)
  zero = ss_vec3_f64(0d0, 0d0, 0d0)
  sphere = ss_sphere_f64(ss_vec3_f64(0d0, 0d0, radius), &
                         ss_vec3_f64(speed * sin(theta), 0d0, -speed * cos(theta)), zero, radius, mass)
  floor_wall = ss_wall_f64(zero, ss_vec3_f64(0d0, 0d0, 1d0), zero)
  state = ss_state_f64(zero, zero, 0d0)
  incoming = sphere%velocity%x
  touched = .false.
  do
    code = ss_sphere_wall_f64(law, sphere, floor_wall, state, f)
    if (code /= SS_OK) stop 2
    if (f%touching == 1) then
      touched = .true.
      code = ss_advance_sphere_f64(law, sphere, f%force_on_j, f%torque_on_j)
    else if (touched) then
      exit
    else
      code = ss_advance_sphere_f64(law, sphere, zero, zero)
    end if
  end do
  write (*, '(I2,1X,F17.15)') angle, sphere%velocity%x / incoming
  call ss_law_free_f64(law)
end program
