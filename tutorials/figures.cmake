# The figures of the tutorials, rendered by satviz-render from tutorials/scenes/ into tutorials/figures/.
# SATVIZ_FIGURE_SCENES: one figure each, as the scene's own view block says (SCENE.png).
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
)
set(SATVIZ_STEP_SCENES
  overlapping_boxes
  circle_and_polygon
  circle_corner
  box_above_floor
)
set(SATVIZ_FACE_STEP_SCENES
  overlapping_boxes
  box_above_floor
)
