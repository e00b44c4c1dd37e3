# Keyboard, sound and screen-reader access: what the window says about them.

select-no-discs = No discs to select: Enter puts one at the centre.
selected-disc-said = Disc { $disc } of { $discs } selected: { $mass }, velocity { $velocity }
launched-at-centre = Disc { $disc } at rest at the centre: with the simulation paused, the arrow keys aim it

## The keyboard path (lines of the help)
keys-focus = Tab / Shift+Tab
help-focus = move through the controls, in reading order; Space or Enter presses one, the arrow keys move a slider; Esc or a click in the world gives the keys back to the world
keys-aim-keys = Arrow keys, paused, with a disc selected
help-aim-keys = aim it: its velocity ±0.1 m/s a press (Shift: ±1 m/s)
keys-select-next = Q / Shift+Q
help-select-next = select the next / the previous disc
keys-launch-centre = Enter
help-launch-centre = a new disc at rest at the centre of the view, selected
keys-in-panels = The keys act on the controls: Esc or a click in the world gives them back to the world.

## Sound
keys-sound = F8
help-sound = sound on / off: a click at each impact, louder for a harder one, higher between discs than at a wall (silent while paused or faster than ×2)
label-toggle-sound = Sound
sound-on = Sound on: a click at each impact (silent while paused or faster than ×2)
sound-off = Sound off
