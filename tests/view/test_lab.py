"""The lab panel: it counts the world's bodies, contacts, joints and sleepers; each of its
widgets' events becomes an action the app carries out (a level, pause, step, restart, an overlay,
the knobs); it follows the app's overlays and knobs; hidden, it takes no events."""

from __future__ import annotations

import pygame
import pygame_gui
import pymunk

from playground import World
from playground.view.app import App
from playground.view.lab import Action, counts
from playground.view.session import Show
from playground.view.tuning import SLIDERS, Knobs

SIZE = (960, 640)


def show(name: str) -> Show:
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    w.track("crate")
    return Show(name=name, world=w, title=name.title())


def lab_app() -> App:
    app = App(show, "a", levels=["a", "b"], size=SIZE)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_l))
    app.run_frames(3)
    return app


def ui(kind: int, element: object, **extra: object) -> pygame.event.Event:
    return pygame.event.Event(kind, ui_element=element, **extra)


def test_counts_bodies_contacts_joints_and_sleepers() -> None:
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("a", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    w.add_box("b", mass=10.0, size=(1.0, 1.0), position=(0.0, 1.5))
    w.space.add(pymunk.PivotJoint(w.body("a"), w.body("b"), (0.0, 1.0)))
    for _ in range(5):
        w.step()
    c = counts(w)
    assert (c.bodies, c.joints) == (2, 1)
    assert c.contacts == 2, "floor–a and a–b"
    assert c.sleeping == 0


def test_buttons_pause_step_and_restart() -> None:
    app = lab_app()
    buttons = app.lab.buttons
    app.handle(ui(pygame_gui.UI_BUTTON_PRESSED, buttons["pause"]))
    assert app.paused and app.frame(1.0 / 60.0) == 0
    steps = app.world.steps
    app.handle(ui(pygame_gui.UI_BUTTON_PRESSED, buttons["step"]))
    assert app.world.steps == steps + 1
    world = app.world
    app.handle(ui(pygame_gui.UI_BUTTON_PRESSED, buttons["restart"]))
    assert app.world is not world and app.world.steps == 0


def test_the_browser_starts_a_level_and_checkboxes_set_overlays() -> None:
    app = lab_app()
    app.handle(ui(pygame_gui.UI_DROP_DOWN_MENU_CHANGED, app.lab.browser, text="b"))
    assert app.level == "b" and app.session.show.title == "B"
    app.handle(ui(pygame_gui.UI_CHECK_BOX_CHECKED, app.lab.boxes["contacts"]))
    assert app.overlay.contacts
    app.handle(ui(pygame_gui.UI_CHECK_BOX_UNCHECKED, app.lab.boxes["vectors"]))
    assert not app.overlay.vectors
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_v))
    assert app.lab.boxes["vectors"].is_checked, "a key's toggle shows on the panel"


def test_a_slider_sets_its_knob_from_the_next_step_on() -> None:
    app = lab_app()
    slider = next(s for s in SLIDERS if s.field == "min_cutoff")
    event = ui(pygame_gui.UI_HORIZONTAL_SLIDER_MOVED, app.lab.sliders["min_cutoff"], value=750)
    action = app.lab.action(event)
    assert isinstance(action, Action) and isinstance(action.value, Knobs)
    app.handle(event)
    assert app.world.config.perception.min_cutoff == slider.value(0.75)


def test_hidden_it_takes_no_mouse_events() -> None:
    app = App(show, "a", size=SIZE)
    press = pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=app.lab.rect.center)
    assert not app.lab.visible and not app.lab.process(press)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_l))
    assert app.lab.process(press)


def test_the_hud_moves_right_of_the_shown_panel() -> None:
    """Law: while the lab panel is shown the HUD's panels start right of it (it hid the title,
    the clock and the player's state); hidden, the HUD is back at the window's edge."""
    app = lab_app()
    app.render()
    title, status = app.hud.rects[:2]
    assert title.left > app.lab.rect.right and status.left > app.lab.rect.right
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_l))
    app.render()
    title, status = app.hud.rects[:2]
    assert title.left == status.left == 8
