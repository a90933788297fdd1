# The figures of the tutorials, rendered by satviz-render from tutorials/scenes/ into tutorials/figures/.
# SATVIZ_FIGURE_SCENES: one figure each, as the scene's own view block says (SCENE.png).
# SATVIZ_STEP_SCENES: one figure per trace step (SCENE-stepN.png), for stepping through the algorithm.
# The committed figures double as the golden images of the render tests.
set(SATVIZ_FIGURE_SCENES
  bullet_wall
  circle_and_polygon
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
)
