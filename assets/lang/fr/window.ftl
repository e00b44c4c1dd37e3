# Les mots de la fenêtre en français : panneaux, barre du haut, onglets, écran d'accueil.
# Chaque autre langue a les mêmes messages avec les mêmes $valeurs.

this-language = Français
language-now = Langue : { this-language }

## La barre du haut
scene-untitled = Bac à sable
scene-edited-mark = (modifiée)
state-rewound = REMBOBINÉ
state-paused = EN PAUSE
state-running = EN COURS
state-stalled = BLOQUÉ
rewound-line = enregistré : de { $oldest } à { $newest } s ; Espace pour reprendre
momentum-hover = quantité de mouvement totale des disques
momentum-walls-push = p = { $momentum } (les murs poussent)
momentum-walls-push-hover = les murs poussent : la quantité de mouvement des disques ne change qu'aux murs ; entre disques, elle se conserve
energy-with-turning = Ec { $moving } + rotation { $turning } = { $total }
energy-with-turning-hover = énergie de translation, ½·m·v², plus énergie de rotation, ½·I·ω² avec I = ½·m·r², additionnées sur tous les disques
energy-line = Ec = { $energy }
energy-hover = énergie cinétique : l'énergie due au mouvement, ½·m·v², additionnée sur tous les disques
count-hover = collisions entre deux disques, et d'un disque contre un mur, comptées à part
com-view-line = vue du centre de masse : p = { $momentum }, Ec = { $energy }
energy-with-height = Ec + Epp = { $energy }
energy-with-height-hover = énergie cinétique (de translation, et de rotation) plus énergie potentielle de pesanteur, nulle au bord inférieur de la boîte
angular-momentum-hover = moment cinétique par rapport au coin (0, 0), dû à la translation et à la rotation : les collisions entre disques le conservent, les murs le modifient
resting-contacts = contacts au repos : { $count }
resting-contacts-hover = disques posés les uns sur les autres ou contre un mur : pas comptés comme des collisions
show-panels = Afficher panneaux
top-bar-more = … plus
running-slower = simulation à { $rate }× le temps réel
running-slower-many = simulation à { $rate }× le temps réel : avec moins de disques, ce serait plus rapide
method-in-use = en cours : { $method } / { $broad }
method-in-use-auto = en cours : { $method } / { $broad } (auto : { $reason })

## Fenêtres au-dessus de la simulation
recovery-title = Restaurer la dernière session ?
recovery-waits = La simulation attend votre réponse.
recovery-restore = Restaurer (R)
recovery-set-aside = Mettre de côté (Échap)
help-title = Clavier et souris
presets-title = Préréglages
reopen-kept-hover = Le bac à sable que ce navigateur avait gardé avant l'ouverture du lien.
presets-press = Appuyez sur la touche, ou cliquez :

## Le bandeau sous la simulation
caption-edited = Avant les modifications : { $caption }
caption-none = Glissez dans le vide pour lancer un disque ; H liste toutes les touches.

## Les grandeurs, comme les nomment les champs et les colonnes
quantity-mass = masse
quantity-radius = rayon
quantity-vx = v_x
quantity-vy = v_y
quantity-x = x
quantity-y = y
quantity-speed = vitesse |v|
quantity-direction = direction
direction-hover = Degrés depuis la droite, dans le sens antihoraire : 0 à droite, 90 en haut, 180 à gauche, −90 en bas

## Les onglets du panneau du bas
tab-totals = Totaux
tab-collisions = Collisions
tab-discs = Disques
tab-speeds = Vitesses
tab-momenta = Vecteurs p

## Les vignettes de l'écran d'accueil
tile-head-on = Choc frontal (1D)
tile-glancing = Choc oblique (2D)
tile-inelastic = Inélastique
tile-pi-blocks = Blocs π
tile-gas = Un gaz
tile-free-play = { scene-untitled }
tile-head-on-blurb = Deux disques se rencontrent sur une droite. La quantité de mouvement totale est-elle la même après ?
tile-glancing-blurb = Un disque en heurte un autre sans le viser au centre. Dans quelles directions partent-ils ?
tile-inelastic-blurb = Des disques qui ne rebondissent pas complètement. Où passe l'énergie ?
tile-pi-blocks-blurb = Un bloc léger, un lourd et un mur : comptez les chocs.
tile-gas-blurb = Beaucoup de disques à la fois : comment leurs vitesses se répartissent-elles ?
tile-free-play-blurb = Lancez vos propres disques et modifiez tout.
lesson-wall-pause = En pause : le disque { $disc } a touché le mur { $wall ->
    [left] de gauche
    [right] de droite
    [bottom] du bas
   *[top] du haut
}, et la poussée d'un mur change la quantité de mouvement totale. { $key } relance.

## L'écran d'accueil
close = Fermer
start-title = Que voulez-vous explorer ?
start-footer = Tab et Entrée choisissent une leçon au clavier. Échap garde la scène ouverte. Le bouton Accueil de la barre du haut fait revenir cet écran.

## Le panneau latéral
controls-for = Les réglages de « { $lesson } ».
selected-disc-numbered = Disque sélectionné ({ $disc })
section-more = Plus
section-more-line = Pour les disques qui tournent, et pour comparer les façons de calculer de l'ordinateur.
play = Lecture
pause = Pause
colour-white = blanc
colour-pink = rose
colour-amber-outlined = ambre, cerclé
colour-black = noir
colour-purple = violet
colour-brown-outlined = marron, cerclé
show-velocity = vecteurs vitesse ({ $colour })
show-velocity-hover = où sera chaque disque dans une demi-seconde
show-momentum = vecteurs p ({ $colour })
show-momentum-hover = quantité de mouvement p = m·v : la masse multipliée par la vitesse
show-delta-p = Δp après une collision ({ $colour })
show-delta-p-hover = la variation de quantité de mouvement de chaque disque, pendant une seconde après chaque collision entre disques (dans les scènes d'au plus { $most } disques : dans un gaz, ils cacheraient les disques)
readouts-none = aucune
readouts-selected = disque sélectionné
readouts-all = tous les disques
readouts-label = valeurs à côté
readouts-hover = là où les étiquettes se recouvriraient, certains disques n'en ont pas ; la simulation indique combien
show-center-of-mass = centre de masse
show-center-of-mass-hover = le point d'équilibre de l'ensemble des disques, et sa vitesse
show-safe-palette = couleurs pour daltoniens
show-com-view = vue du centre de masse
show-com-view-hover = la vue se déplace avec le centre de masse et les vecteurs montrent les vitesses par rapport à lui (référentiel du centre de masse) ; l'expérience n'est pas modifiée

## La section Collisions
restitution-label = Rebond entre disques, coefficient de restitution e
restitution-scale = 1 : ils rebondissent complètement, 0 : ils repartent ensemble le long de la ligne d'impact
restitution-hover = La part de leur vitesse d'approche que deux disques gardent en s'éloignant, le long de la droite qui joint leurs centres : 1 pour toute, 0 pour rien (le mouvement de côté est conservé)
wall-restitution-label = Rebond sur les murs, coefficient de restitution e
wall-restitution-hover = La part de sa vitesse vers un mur qu'un disque garde en s'en éloignant : 1 pour toute, 0 pour rien
gravity-label = Pesanteur, vers le bas
gravity-hover = l'intensité de la pesanteur qui tire les disques vers le bas ; { $gravity } m/s² sur Terre
edges-label = bords
edges-box = boîte
edges-open = ouverts
edges-periodic = périodiques
edges-hover = Ce que font les côtés de la boîte : boîte, des murs sur lesquels les disques rebondissent ; ouverts, pas de murs (les disques s'envolent) ; périodiques, un disque qui sort d'un côté revient par l'autre
time-scale-label = échelle de temps
time-scale-hover = secondes simulées par seconde réelle : en dessous de 1, c'est du ralenti
roughness-hover = Comment les bords qui se touchent accrochent lors d'une collision, ce qui fait tourner les disques ou arrête leur rotation : −1 lisse (pas d'accroche, aucune rotation donnée), 0 leur glissement s'arrête, 1 parfaitement rugueux (le glissement s'inverse et aucune énergie n'est perdue)
roughness-label = Accroche entre disques, rugosité β (−1 lisse … 1 rugueux)
wall-roughness-label = Accroche aux murs, rugosité β
friction-on-label = Le frottement μ limite l'accroche
friction-hover = Frottement : la poussée de côté là où les disques se touchent vaut au plus μ fois la poussée de face, donc un glissement rapide est seulement freiné ; il fait aussi frotter les disques posés les uns sur les autres. Désactivé : pas de limite.
friction-label = Frottement μ

## Les nouveaux disques et le disque sélectionné
new-discs-line = Glissez dans le vide pour en lancer un.
size-follows-mass = taille selon la masse (même masse volumique)
size-follows-mass-hover = un disque de 1 kg a un rayon de 0,4 m ; le rayon croît comme √m, pour les nouveaux disques et les masses modifiées
radius-from-mass = Rayon { $radius } (d'après la masse)
radius-label = Rayon
mass-label = Masse
new-mass-hover = Les nouveaux disques pèsent de 0,01 à 100 kg : un curseur a besoin de deux bornes, et celles-ci donnent des rapports de masses jusqu’à 10 000 pour 1. Un disque déjà dans la boîte prend n’importe quelle masse : tapez-la dans l’onglet Disques ou sous Disque sélectionné
selected-none = Aucun : cliquez sur un disque pour le sélectionner.
apply = Appliquer
apply-hover = Entrée dans un champ

## Les sections Scène et Vue
preset-label = préréglage
preset-choose = ouvrir un préréglage…
scene-drop = Ouvrir un fichier de scène : déposez-le sur la page.
scene-file-label = Fichier de scène :
scene-file-hint = p. ex. assets/scenes/preset-8-gas.toml
scene-name-label = Nom :
scene-name-hover = Le nom de la scène : il s'affiche en haut de la fenêtre et nomme les fichiers où elle est enregistrée. Tapez-en un et appuyez sur Entrée.
open = Ouvrir
open-hover = Entrée dans le champ
share = Partager le lien
share-hover = met cette scène dans l'adresse de la page, pour l'envoyer sous forme de lien
saves-download = Les sauvegardes, exports et captures d'écran sont téléchargés sous forme de fichiers.
saves-go-to = Les sauvegardes vont dans { $folder }/
ui-scale-label = Taille du texte et des commandes
theme-light = Thème clair
theme-dark = Thème sombre
theme-hover = une salle bien éclairée demande le thème clair
language-label = langue
language-hover = la langue de la fenêtre ; les nombres la suivent (2,5 en français, 2.5 en anglais)

## Détails (sous Plus)
method-label = méthode
method-hover = Comment l'ordinateur calcule les collisions : auto choisit ; exact trouve chacune à son instant précis ; les autres avancent par petits pas de temps fixes et corrigent les chevauchements
broad-phase-label = phase large
broad-phase-hover = Comment l'ordinateur repère les disques proches les uns des autres avant de les examiner de près : cela ne change que la vitesse de calcul, pas le résultat
substeps-label = sous-pas
substeps-hover = En combien de pas plus petits chaque pas de temps est découpé : plus il y en a, plus c'est précis, et lent
dt-line = pas de temps dt = { $dt }
dt-hover = la durée simulée que couvre un pas de calcul de l'ordinateur
step-time-line = durée d'un pas { $time } (médiane), { $steps } pas dans la dernière image
fps-line = { $fps } images par seconde
sim-rate-line = secondes simulées par seconde réelle : { $rate }
page-title = Impulse : collisions de disques

## L'onglet Totaux
symbol-ke = Ec
totals-energy = énergie
totals-kinetic-energy = énergie cinétique
totals-momentum = quantité de mouvement
totals-angular-momentum = moment cinétique L
totals-change = Variation depuis t = { $since } : { $p_name } { $momentum }, { $l_name } { $angular }, { $e_name } { $energy }
totals-change-line = Variation depuis t = { $since } : { $p_name } { $momentum }, { $e_name } { $energy }
totals-change-wrapping = Variation depuis t = { $since } : { $p_name } { $momentum }, { $e_name } { $energy } ; { $l_name } n'est pas conservé quand des disques passent d'un bord à l'autre
totals-none = Rien d'enregistré pour l'instant : lancez la simulation.
totals-rotational-ke = Ec de rotation
totals-ke-sum = Ec + Ec de rotation
totals-sum = somme
totals-hover = p : quantité de mouvement, masse multipliée par vitesse, additionnée sur tous les disques. L : moment cinétique, qui mesure à quel point les disques tournent autour du coin inférieur gauche de la boîte (0, 0) et sur eux-mêmes. Les collisions entre disques conservent les deux ; les poussées des murs les modifient (des lignes pointillées marquent où). E : l'énergie du mouvement (Ec), et, pour des disques qui tournent, aussi celle de la rotation.
totals-hover-wrapping = Dans ce monde, les bords se rejoignent : un disque qui sort d'un côté revient par le côté opposé. Sa quantité de mouvement ne change pas, mais sa position par rapport à (0, 0) saute, donc L saute aussi ; ce n'est pas une erreur des collisions.
totals-walls-push = les murs poussent
axis-time = temps (s)
axis-energy = énergie (J)

## L'onglet Collisions (le registre)
ledger-pair = disques { $a } et { $b }
ledger-wall = disque { $disc } et le mur { $wall ->
    [left] de gauche
    [right] de droite
    [bottom] du bas
   *[top] du haut
}
ledger-empty = Aucune pour l'instant. Collision suivante (J) avance jusqu'à la prochaine, entre disques ou avec un mur, et s'arrête à l'instant du choc.
ledger-last = { $count ->
    [one] La dernière
   *[other] Les { $count } dernières, la plus récente en premier
}
ledger-time-hover = quand elle a eu lieu
ledger-what = quoi
ledger-what-hover = quels disques, ou quel disque et quel mur
ledger-dp-hover = la variation de la quantité de mouvement totale des disques concernés : nulle entre disques, égale à la poussée du mur pour un choc contre un mur
ledger-dke-hover = la variation de leur énergie cinétique, l'énergie du mouvement : nulle lors d'un choc élastique, négative quand une partie est perdue
ledger-newest = { $who }, { $when }
ledger-disc-p = disque { $disc } : p (kg·m/s)
ledger-disc-ke = disque { $disc } : { $ke } (J)
ledger-disc-v = disque { $disc } : v { $part } (m/s)
ledger-both-p = les deux : p (kg·m/s)
ledger-both-ke = les deux : { $ke } (J)
ledger-along-impact = selon la ligne d'impact
ledger-across-impact = perpendiculaire
ledger-away-from-wall = en s'éloignant du mur
ledger-along-wall = le long du mur
ledger-wall-push = la poussée du mur, Δp (kg·m/s)
ledger-before = avant
ledger-after = après
ledger-detail-hover = La ligne d'impact passe par les centres des deux disques (ou va du mur au disque) à l'instant où ils se touchent ; lors d'une collision de disques lisses, seule la vitesse le long de cette ligne change. Le long de cette ligne, le sens positif va du disque nommé en premier vers l'autre (contre un mur, il s'éloigne du mur).

## L'onglet Disques
table-spin = rotation ω
    (rad/s)
table-spin-hover = la vitesse de rotation du disque : en radians par seconde, positive dans le sens inverse des aiguilles d'une montre
table-rotational-ke-hover = l'énergie de sa rotation, ½·I·ω² avec I = ½·m·r²
table-angular-momentum-hover = moment cinétique, qui mesure à quel point le disque tourne autour du coin inférieur gauche de la boîte (0, 0) et sur lui-même : m·(x·v_y − y·v_x) pour sa translation plus I·ω pour sa rotation
table-disc = disque
table-line = Cliquez sur une masse ou une vitesse pour la modifier ; Entrée applique, Échap annule.
table-no-discs = Aucun disque : glissez dans le vide pour en lancer un.

## La rangée d'onglets du panneau et l'onglet Vecteurs p
dock-hide = Masquer
dock-show = Afficher
dock-no-room = pas de place ici : L masque le panneau latéral
dock-no-room-drawer = pas de place ici à cette taille de texte : { $key } la change
momenta-no-discs = Aucun disque.
momenta-too-many = Total : { $total }. Trop de disques ({ $count }) pour dessiner un vecteur par disque ; le diagramme en dessine jusqu’à { $most }.
momenta-line = Total (épais) : { $total }, les quantités de mouvement des disques mises bout à bout, chacune dans sa couleur
momenta-hover = { $line } ; p_x et p_y sont tracés à la même échelle, donc les angles sont exacts
disc-numbered = disque { $disc }
readout-disc = { $disc } :

## L'onglet Vitesses
speeds-axis-rim = vitesse, vitesse du bord (m/s)
speeds-axis = vitesse (m/s)
speeds-name = vitesses |v|
speeds-discs = disques
speeds-count = disques par barre
# Hovering a bar: how many discs it counts, and its speeds.
speeds-bar = { $count ->
    [one] un disque
   *[other] { $count } disques
} de { $low } à { $high } m/s
maxwell-boltzmann = Maxwell–Boltzmann
rim-speeds = vitesses du bord |ω|·r
rim-speeds-equal = vitesses du bord, à parts égales
speeds-too-few = Trop peu de disques en mouvement pour une distribution : essayez le préréglage 8, un gaz.
speeds-line = Barres : combien de disques vont à chaque vitesse. Courbe : où se stabilise un gaz (Maxwell–Boltzmann).
speeds-line-few = Barres : combien de disques vont à chaque vitesse. La courbe d'un gaz (Maxwell–Boltzmann) apparaît dès { $n } disques : essayez le préréglage 8.
speeds-hover = { $line }
    La courbe montre où finissent les vitesses une fois que les collisions ont réparti l'énergie au hasard, pour des disques ayant chacun cette énergie en moyenne : kT = Ec/N = { $kt } (la température, en énergie par disque).
speeds-rim-meaning = Barres : combien de disques se déplacent (ou font tourner leur bord) à chaque vitesse. Courbes : où ils se stabilisent quand l'énergie est partagée à parts égales, à la température kT = Ec/N = { $kt } : Maxwell–Boltzmann pour les vitesses (trait plein) et pour les vitesses du bord (pointillés).
rim-speeds-hover = La vitesse à laquelle le bord de chaque disque se déplace quand il tourne : sa vitesse angulaire ω multipliée par son rayon r.
    { $meaning }
shares-energy = énergie :
shares-energy-hover = la part de l'énergie (%) dans la translation et dans la rotation
shares-moving = translation
shares-turning = rotation
shares-one-third = un tiers
shares-one-third-hover = Si l'énergie est partagée à parts égales entre les trois façons dont un disque la stocke (translation selon x, selon y, rotation), la rotation en reçoit un tiers
shares-moving-ke = translation (Ec)
shares-turning-ke = rotation (Ec de rotation)

## Dans la simulation
readout-spin = rotation ω = { $spin }   Ec de rotation = { $energy }
readout-angular-momentum = moment cinétique par rapport à (0, 0) : L = { $angular }
readouts-culled = { $wanted ->
    [one] pas de place ici pour les valeurs du disque sélectionné (zoomez avec la molette)
   *[other] valeurs à côté de { $shown } disques sur { $wanted } : pas de place pour les autres (zoomez avec la molette)
}
launch-no-room = pas de place ici
gas-name = Gaz de { $count } disques
gas-description = { $count } disques identiques couvrant 30 % d'une boîte périodique (--gas { $count })
tab-edge = Hauteur de l'onglet
tab-edge-hover = Faites glisser pour agrandir ou réduire l'onglet. Au clavier (Tab jusqu'ici) : les flèches une ligne, Début le plus haut, Fin le plus bas, Entrée sa hauteur d'origine ; ou double-clic.
