# Keyboard, sound and screen-reader access: what the window says about them.

select-no-discs = No discs to select: Enter puts one at the centre.
selected-disc-said = Disc { $disc } of { $discs } selected: { $mass }, velocity { $velocity }
launched-at-centre = Disc { $disc } at rest at the centre: with the simulation paused, the arrow keys aim it
launched-near-centre = Disc { $disc } at rest beside disc { $beside } (the centre was taken): with the simulation paused, the arrow keys aim it

## The keyboard path (lines of the help)
keys-focus = Tab / Shift+Tab
help-focus = move through the controls, in reading order; Space or Enter presses one, the arrow keys move a slider, step through a drop-down's choices or scroll a list (Page Up, Page Down, Home and End too); Esc or a click in the world makes the shortcut keys work again
keys-regions = F6 / Shift+F6
help-regions = jump to the next part of the window: the controls (opened if closed; the selected disc's mass first), the tabs, the top bar, and back to the world; Tab then moves within it
keys-aim-keys = Arrow keys, paused, with a disc selected
help-aim-keys = aim it: its velocity ±0.1 m/s a press (Shift: ±1 m/s)
keys-select-next = Q / Shift+Q
help-select-next = select the next / the previous disc
keys-launch-centre = Enter
help-launch-centre = a new disc at rest at the centre of the view, selected; in a lesson waiting on its question, plays it
keys-in-panels = The keys work the controls now: Esc or a click in the world makes the shortcut keys work again.
keys-in-panels-short = Esc: shortcut keys again
keys-tab-edge = Tab height: arrows a row, Home tallest, End shortest, Enter: its own height. Esc: shortcut keys again.
keys-tab-edge-short = Arrows, Home, End: tab height
keys-after-field = Space, N and J act on the simulation; the other shortcut keys wait: Esc or a click in the world makes them work again.

## Sound
keys-sound = F8
help-sound = sound on / off: a click at each impact, louder for a harder one, higher between discs than at a wall (silent while paused or faster than ×2)
label-toggle-sound = Sound
sound-on = Sound on: a click at each impact (silent while paused or faster than ×2)
sound-off = Sound off

## Said to a screen reader (the browser's live region, the In words tab)
said-pair = Disc { $a } hit disc { $b }: their total momentum before { $before }, after { $after }
said-wall = Disc { $disc } hit the { $wall ->
    [left] left
    [right] right
    [bottom] bottom
   *[top] top
} wall: speed before { $before }, after { $after }
place-middle = in the middle
place-left = at the left
place-right = at the right
place-bottom = at the bottom
place-top = at the top
place-bottom-left = at the bottom left
place-bottom-right = at the bottom right
place-top-left = at the top left
place-top-right = at the top right
motion-rest = at rest
motion-moving = moving { $direction } at { $speed }
direction-right = right
direction-up-right = up and to the right
direction-up = up
direction-up-left = up and to the left
direction-left = left
direction-down-left = down and to the left
direction-down = down
direction-down-right = down and to the right
describe-box = { $discs ->
    [one] One disc
   *[other] { $discs } discs
} in a { $width } by { $height } metre { $edges ->
    [open] space without walls.
    [periodic] space whose sides join up (a disc leaving on one side comes back on the other).
   *[box] box.
}
describe-gravity = Gravity pulls down at { $gravity }.
describe-no-gravity = No gravity.
describe-restitution = Restitution between discs: { $restitution }.
describe-disc = Disc { $disc }, { $mass }, { $place }, { $motion }.
describe-more = And { $more } more discs; their mean speed is { $speed }.
describe-totals = { $state ->
    [paused] Paused
   *[running] Running
} at t = { $time }; total momentum { $momentum }, kinetic energy { $energy }.
tab-words = In words
# On the desktop; in the browser, where a screen reader reads the page.
words-line = What happens, in words, newest first: one impact every { $gap } s at most (the { tab-collisions } tab lists them all).
words-line-web = What happens, in words, newest first, as a screen reader reads it: one impact every { $gap } s at most (the { tab-collisions } tab lists them all).
words-none = Nothing said yet.
label-describe = Describe the scene
mirror-title = Impulse: controls for the keyboard and screen readers
mirror-canvas = Impulse, the simulation: { $keys } lists the keys
mirror-said = What happens
