# The figures of the tutorials, rendered by satviz-render from tutorials/scenes/ into tutorials/figures/.
# SATVIZ_FIGURE_SCENES: one figure each, as the scene's own view block says (SCENE.png); a view with "sim_steps"
# steps the scene's world that many times first.
# SATVIZ_STEP_SCENES: one figure per trace step (SCENE-stepN.png, N from 1), for stepping through the textbook test.
# SATVIZ_FACE_STEP_SCENES: the same in the face-test view (--view faces), in figures/faces/.
# The committed figures double as the golden images of the render tests.
set(SATVIZ_FIGURE_SCENES
  box_above_floor
  bullet_wall
  circle_and_polygon
  circle_corner
  containment
  far_from_origin
  fly_by
  many_sides
  overlapping_boxes
  parallel_boxes
  separated_triangle
  sliding_past
  two_circles
  l02_box_and_triangle
  l04_wrong_way
  l05_naive_push
  l06_plank_over_ledge
  l06_tilted_plank
  l09_landing
  l09_stuck
  l10_ray_miss
  l10_round_bullet
  l11_decimal_touch
  l11_float_seen
  l12_apart
  l13_overlap
  l13_apart
  l13_sweep
  pitfall_direction
  pitfall_float
  pitfall_one_shape
  pitfall_tunnel
  pitfall_unnormalised
  l14_head_on
  l14_head_on_after
  l14_slide
  l14_slide_after
  l15_slope
  l15_slope_sticks
  l15_slope_slides
)
set(SATVIZ_STEP_SCENES
  overlapping_boxes
  circle_and_polygon
  circle_corner
  box_above_floor
  l01_triangle_and_ball
  l03_corner_gap
  l05_box_in_box
  l07_near_miss
  l08_throw
  l10_ray_hit
)
set(SATVIZ_FACE_STEP_SCENES
  overlapping_boxes
  box_above_floor
)
