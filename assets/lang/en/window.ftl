# The window's words in English: panels, top bar, tabs, the start screen.
# Every other language has the same messages with the same $values.

this-language = English
language-now = Language: { this-language }

## The top bar
scene-untitled = Sandbox
scene-edited-mark = (edited)
state-rewound = REWOUND
state-paused = PAUSED
state-running = RUNNING
state-stalled = STUCK
rewound-line = recorded: { $oldest } to { $newest } s; Space resumes
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
running-slower-many = running at { $rate }× real time: fewer discs would run faster
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
caption-edited = Before the edits: { $caption }
caption-none = Drag on empty space to launch a disc; H lists every key.

## Quantities, as fields and columns name them
quantity-mass = mass
quantity-radius = radius
quantity-vx = v_x
quantity-vy = v_y
quantity-x = x
quantity-y = y
quantity-speed = speed |v|
quantity-direction = direction
direction-hover = Degrees from the right, turning anticlockwise: 0 right, 90 up, 180 left, −90 down

## The bottom dock's tabs
tab-totals = Totals
tab-collisions = Collisions
tab-discs = Discs
tab-speeds = Speeds
tab-momenta = Momenta

## The start screen's tiles
tile-head-on = Head-on (1D)
tile-glancing = Glancing (2D)
tile-inelastic = Inelastic
tile-pi-blocks = π blocks
tile-gas = A gas
tile-free-play = { scene-untitled }
tile-head-on-blurb = Two discs meet on a line. Is the total momentum the same after?
tile-glancing-blurb = One disc hits another off-centre. Which way do they go?
tile-inelastic-blurb = Discs that do not bounce back fully. Where does the energy go?
tile-pi-blocks-blurb = A light block, a heavy one and a wall: count the bumps.
tile-gas-blurb = Many discs at once: how are their speeds shared out?
tile-free-play-blurb = Launch your own discs and change everything.
lesson-wall-pause = Paused: disc { $disc } hit the { $wall ->
    [left] left
    [right] right
    [bottom] bottom
   *[top] top
} wall, and a wall's push changes the total momentum. { $key } runs on.

## The start screen
close = Close
start-title = What would you like to explore?
start-footer = Tab and Enter choose a lesson from the keyboard. Esc keeps the scene that is open. The Start button in the top bar brings this back.

## The side dock
controls-for = The controls for “{ $lesson }”.
selected-disc-numbered = Selected disc ({ $disc })
section-more = More
section-more-line = For spinning discs, and for comparing how the computer works it out.
play = Play
pause = Pause
colour-white = white
colour-pink = pink
colour-amber-outlined = amber, outlined
colour-black = black
colour-purple = purple
colour-brown-outlined = brown, outlined
show-velocity = velocity arrows ({ $colour })
show-velocity-hover = where each disc will be half a second from now
show-momentum = momentum arrows ({ $colour })
show-momentum-hover = momentum p = m·v: mass times velocity
show-delta-p = Δp after a collision ({ $colour })
show-delta-p-hover = each disc's change of momentum, for a second after each collision between discs (in scenes of up to { $most } discs: in a gas they would hide the discs)
readouts-none = none
readouts-selected = selected disc
readouts-all = every disc
readouts-label = values beside
readouts-hover = where labels would cover each other, some discs go without; the world says how many
show-center-of-mass = centre of mass
show-center-of-mass-hover = the balance point of all the discs, and its velocity
show-safe-palette = colour-blind-safe
show-com-view = centre-of-mass view
show-com-view-hover = the view moves with the centre of mass and arrows show velocities relative to it; the experiment is not changed

## The Collisions section
restitution-label = Bounce between discs, restitution e
restitution-scale = 1: they bounce back fully, 0: they move on together along the line of impact
restitution-hover = How much of their approach speed two discs keep, going apart, along the line through their centres: 1 all of it, 0 none (sideways motion is kept)
wall-restitution-label = Bounce at the walls, restitution e
wall-restitution-hover = How much of its speed into a wall a disc keeps, going away from it: 1 all of it, 0 none
gravity-label = Gravity, pointing down
gravity-hover = how hard the discs are pulled down; { $gravity } m/s² on Earth
edges-label = edges
edges-box = box
edges-open = open
edges-periodic = periodic
edges-hover = What the sides of the box do: box, walls the discs bounce off; open, no walls (discs fly away); periodic, a disc leaving on one side comes back on the other
time-scale-label = time scale
time-scale-hover = simulated seconds per real second: below 1 is slow motion
roughness-hover = How the touching edges grip in a collision, so that discs start or stop spinning: −1 smooth (no grip, no spin given), 0 their sliding stops, 1 perfectly rough (the sliding reverses and no energy is lost)
roughness-label = Grip between discs, roughness β (−1 smooth … 1 rough)
wall-roughness-label = Grip at the walls, roughness β
friction-on-label = Friction μ limits the grip
friction-hover = Friction: the sideways push where discs touch is at most μ times the head-on push, so fast sliding is only slowed; it also makes discs lying on each other rub. Off: no limit.
friction-label = Friction μ

## New discs and the selected disc
new-discs-line = Drag on empty space to launch one.
size-follows-mass = size follows mass (same density)
size-follows-mass-hover = a 1 kg disc is 0.4 m in radius; the radius grows as √m, for new discs and mass edits
radius-from-mass = Radius { $radius } (from the mass)
radius-label = Radius
mass-label = Mass
new-mass-hover = New discs take 0.01 to 100 kg: a slider needs two ends, and these reach mass ratios of 10 000 to 1. A disc already in the box takes any mass: type it in the Discs tab or under Selected disc
selected-none = None: click a disc to select it.
apply = Apply
apply-hover = Enter in a field

## The Scene and View sections
preset-label = preset
preset-choose = open a preset…
scene-drop = Open a scene file: drop it on the page.
scene-file-label = Scene file:
scene-file-hint = e.g. assets/scenes/preset-8-gas.toml
scene-name-label = Name:
scene-name-hover = The scene's name: it heads the window and names the files it is saved under. Type one and press Enter.
open = Open
open-hover = Enter in the field
share = Share link
share-hover = puts this scene into the page's address, to send as a link
saves-download = Saves, exports and screenshots download as files.
saves-go-to = Saves go to { $folder }/
ui-scale-label = Size of text and controls
theme-light = Light theme
theme-dark = Dark theme
theme-hover = a bright room wants the light one
language-label = language
language-hover = the language of the window; numbers follow it (2,5 or 2.5)

## Details (under More)
method-label = method
method-hover = How the computer works out the collisions: auto chooses; exact finds each one at its instant; the others step in small fixed times and correct overlaps
broad-phase-label = broad phase
broad-phase-hover = How the computer finds which discs are near each other before checking them closely: it only changes the speed, not the result
substeps-label = substeps
substeps-hover = How many smaller steps each time step is cut into: more is more accurate and slower
dt-line = time step dt = { $dt }
dt-hover = how much simulated time one step of the computer covers
step-time-line = step time { $time } (median), { $steps } steps in the last frame
fps-line = { $fps } frames per second
sim-rate-line = simulated seconds per real second: { $rate }
page-title = Impulse: collisions of discs

## The Totals tab
symbol-ke = KE
totals-energy = energy
totals-kinetic-energy = kinetic energy
totals-momentum = momentum
totals-angular-momentum = angular momentum L
totals-change = Change since t = { $since }: { $p_name } { $momentum }, { $l_name } { $angular }, { $e_name } { $energy }
totals-change-line = Change since t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }
totals-change-wrapping = Change since t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }; { $l_name } is not kept when discs wrap round the edges
totals-none = No record yet: run the simulation.
totals-rotational-ke = rotational KE
totals-ke-sum = KE + rotational KE
totals-sum = sum
totals-hover = p: momentum, mass times velocity, added up over the discs. L: angular momentum, how much the discs go round the box's bottom-left corner (0, 0) and turn. Collisions between discs keep both; the walls' pushes change them (dashed lines mark where). E: the energy of moving (KE), and with spinning discs of turning too.
totals-hover-wrapping = In this world the edges wrap round: a disc leaving on one side comes back on the other. Its momentum stays the same, but its place about (0, 0) jumps, so L jumps too; that is not a fault of the collisions.
totals-walls-push = walls push
axis-time = time (s)
axis-energy = energy (J)

## The Collisions tab (the ledger)
ledger-pair = discs { $a } and { $b }
ledger-wall = disc { $disc } and the { $wall ->
    [left] left
    [right] right
    [bottom] bottom
   *[top] top
} wall
ledger-empty = None yet. Next collision (J) runs to the next one, between discs or with a wall, and pauses at the instant of impact.
ledger-last = { $count ->
    [one] The last one
   *[other] The last { $count }, newest first
}
ledger-time-hover = when it happened
ledger-what = what
ledger-what-hover = which discs, or which disc and wall
ledger-dp-hover = the change of the total momentum of the discs in it: zero between discs, the wall's push at a wall
ledger-dke-hover = the change of their kinetic energy, the energy of moving: zero in an elastic collision, less than zero when some is lost
ledger-newest = { $who }, { $when }
ledger-disc-p = disc { $disc }: p (kg·m/s)
ledger-disc-ke = disc { $disc }: { $ke } (J)
ledger-disc-v = disc { $disc }: v { $part } (m/s)
ledger-both-p = both discs: p (kg·m/s)
ledger-both-ke = both discs: { $ke } (J)
ledger-along-impact = along the line of impact
ledger-across-impact = across it
ledger-away-from-wall = away from the wall
ledger-along-wall = along the wall
ledger-wall-push = the wall's push, Δp (kg·m/s)
ledger-before = before
ledger-after = after
ledger-detail-hover = The line of impact runs through the centres of the two discs (or from the wall to the disc) at the instant they touch; only the speed along it changes in a smooth collision. Along it, plus points from the disc named first towards the other (at a wall, away from the wall).

## The Discs tab
table-spin = spin ω
    (rad/s)
table-spin-hover = how fast the disc turns: radians per second, anticlockwise positive
table-rotational-ke-hover = the energy of its turning, ½·I·ω² with I = ½·m·r²
table-angular-momentum-hover = angular momentum, how much the disc goes round the box's bottom-left corner (0, 0) and turns: m·(x·v_y − y·v_x) of its moving plus I·ω of its turning
table-disc = disc
table-line = Click a mass or velocity to change it; Enter applies, Esc cancels.
table-no-discs = No discs: drag on empty space to launch one.

## The dock's tab row and the Momenta tab
dock-hide = Hide
dock-show = Show
dock-no-room = no room here: L hides the side panel
dock-no-room-drawer = no room here at this text size: { $key } changes it
momenta-no-discs = No discs.
momenta-too-many = Total: { $total }. Too many discs ({ $count }) to draw one arrow each; the diagram draws up to { $most }.
momenta-line = Total (thick): { $total }, each disc's momentum tip to tail in its colour
momenta-hover = { $line }; p_x and p_y are drawn to one scale, so angles are true
disc-numbered = disc { $disc }
readout-disc = { $disc }:

## The Speeds tab
speeds-axis-rim = speed, rim speed (m/s)
speeds-axis = speed (m/s)
speeds-name = speeds |v|
speeds-discs = discs
speeds-count = discs in each bar
# Hovering a bar: how many discs it counts, and its speeds.
speeds-bar = { $count ->
    [one] one disc
   *[other] { $count } discs
} from { $low } to { $high } m/s
maxwell-boltzmann = Maxwell–Boltzmann
rim-speeds = rim speeds |ω|·r
rim-speeds-equal = rim speeds, shared equally
speeds-too-few = Too few moving discs for a distribution: try preset 8, a gas.
speeds-line = Bars: how many discs move at each speed. Curve: how a gas settles (Maxwell–Boltzmann).
speeds-line-few = Bars: how many discs move at each speed. A gas's curve (Maxwell–Boltzmann) shows from { $n } discs: try preset 8.
speeds-hover = { $line }
    The curve is where the speeds end up once collisions have shared the energy out at random, for discs with this much energy each on average: kT = KE/N = { $kt } (the temperature, in energy per disc).
speeds-rim-meaning = Bars: how many discs move (or turn their edge) at each speed. Curves: where they settle when the energy is shared equally, at the temperature kT = KE/N = { $kt }: Maxwell–Boltzmann for the speeds (solid), and for the rim speeds (dashed).
rim-speeds-hover = How fast the edge of each disc moves as it turns: its spin ω times its radius r.
    { $meaning }
shares-energy = energy:
shares-energy-hover = the share of the energy (%) in moving and in turning
shares-moving = moving
shares-turning = turning
shares-one-third = one third
shares-one-third-hover = Shared equally among the three ways a disc holds energy (moving along x, along y, turning), turning gets one third
shares-moving-ke = moving (KE)
shares-turning-ke = turning (rotational KE)

## In the world
readout-spin = spin ω = { $spin }   rotational KE = { $energy }
readout-angular-momentum = angular momentum about (0, 0): L = { $angular }
readouts-culled = { $wanted ->
    [one] no room here for the selected disc's values (zoom in with the wheel)
   *[other] values beside { $shown } of { $wanted } discs: no room for the rest (zoom in with the wheel)
}
launch-no-room = no room here
gas-name = Gas of { $count } discs
gas-description = { $count } equal discs covering 30 % of a periodic box (--gas { $count })
tab-edge = Height of the tab
tab-edge-hover = Drag to make the tab taller or shorter. From the keyboard (Tab to here): the arrows a row, Home the tallest, End the shortest, Enter its own height; or double-click.
