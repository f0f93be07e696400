! One Kharaz impact at 20 degrees (talk's parameters, Model AA, dt = t_c/50) through the
! soft-sphere C ABI from Fortran, through the module soft_sphere (soft_sphere.f90). Prints
! "angle e_t".
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
  floor_wall = ss_wall_f64(zero, ss_vec3_f64(0d0, 0d0, 1d0), zero, 0d0, 0d0)
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
