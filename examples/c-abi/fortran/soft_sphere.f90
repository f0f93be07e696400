! The soft-sphere C ABI's Fortran interface (iso_c_binding): the types and the entry points
! of a single contact in f64. `examples/c-abi/install.sh` installs it compiled (gfortran's
! soft_sphere.mod, in the prefix's include directory) and as source (share/soft-sphere/fortran).
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
    type(ss_vec3_f64) :: point, direction, velocity
    real(c_double) :: radius, spin
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
