# The window's words in English: panels, top bar, tabs, the start screen.
# Every other language has the same messages with the same $values.

this-language = English

## The top bar
scene-untitled = Sandbox
state-rewound = REWOUND
state-paused = PAUSED
state-running = RUNNING
rewound-line = rewound to snapshot { $snapshot } of { $snapshots } ({ $oldest } to { $newest } s): Space resumes
momentum-hover = total momentum of the discs
momentum-walls-push = p = { $momentum } (walls push)
momentum-walls-push-hover = walls push: the discs' momentum changes only at the walls; between discs it is kept
energy-with-turning = KE { $moving } + turning { $turning } = { $total }
energy-with-turning-hover = energy of moving, ½·m·v², plus of turning, ½·I·ω² with I = ½·m·r², summed over the discs
energy-line = KE = { $energy }
energy-hover = kinetic energy: the energy of moving, ½·m·v², summed over the discs
count-hover = impacts between two discs, and of a disc on a wall, counted apart
com-view-line = centre-of-mass view: p = { $momentum }, KE = { $energy }
energy-with-height = KE + PE = { $energy }
energy-with-height-hover = energy of moving (and turning) plus the energy of height, zero at the bottom edge of the box
angular-momentum-hover = angular momentum about the corner (0, 0), of moving and of turning: collisions between discs keep it, walls change it
resting-contacts = resting contacts: { $count }
resting-contacts-hover = discs lying on each other or on a wall: not counted as collisions
show-panels = Show panels
top-bar-more = … more
running-slower = running at { $rate }× real time
method-in-use = in use: { $method } / { $broad }
method-in-use-auto = in use: { $method } / { $broad } (auto: { $reason })

## Windows over the world
recovery-title = Restore the last session?
recovery-waits = The simulation waits until you answer.
recovery-restore = Restore (R)
recovery-set-aside = Set it aside (Esc)
help-title = Keys and mouse
presets-title = Presets
reopen-kept-hover = The sandbox this browser kept before the link opened.
presets-press = Press the key, or click:

## The strip under the world
caption-edited = Edited since it opened, so this may no longer hold: { $caption }
caption-none = Drag on empty space to launch a disc; H lists every key.
