# As palavras da janela em português do Brasil: painéis, barra de cima, abas, tela inicial.
# Todo idioma tem as mesmas mensagens com os mesmos $values.

this-language = Português (Brasil)
language-now = Idioma: { this-language }

## A barra de cima
scene-untitled = Caixa livre
scene-edited-mark = (com alterações)
state-rewound = REBOBINADO
state-paused = PAUSADO
state-running = RODANDO
state-stalled = TRAVADO
rewound-line = gravado: { $oldest } a { $newest } s; Espaço continua
momentum-hover = quantidade de movimento total dos discos
momentum-walls-push = p = { $momentum } (paredes empurram)
momentum-walls-push-hover = paredes empurram: a quantidade de movimento dos discos só muda nas paredes; entre discos ela se conserva
energy-with-turning = Ec { $moving } + rotação { $turning } = { $total }
energy-with-turning-hover = energia do movimento, ½·m·v², mais a da rotação, ½·I·ω² com I = ½·m·r², somadas para todos os discos
energy-line = Ec = { $energy }
energy-hover = energia cinética: a energia do movimento, ½·m·v², somada para todos os discos
count-hover = choques entre dois discos, e de um disco com uma parede, contados separadamente
com-view-line = vista do centro de massa: p = { $momentum }, Ec = { $energy }
energy-with-height = Ec + Ep = { $energy }
energy-with-height-hover = energia do movimento (e da rotação) mais a energia potencial da altura, zero na borda inferior da caixa
angular-momentum-hover = momento angular em relação ao canto (0, 0), do movimento e da rotação: as colisões entre discos o conservam, as paredes o alteram
resting-contacts = contatos em repouso: { $count }
resting-contacts-hover = discos apoiados uns nos outros ou numa parede: não contam como colisões
show-panels = Mostrar painéis
top-bar-more = … mais
running-slower = rodando a { $rate }× o tempo real
running-slower-many = rodando a { $rate }× o tempo real: com menos discos seria mais rápido
method-in-use = em uso: { $method } / { $broad }
method-in-use-auto = em uso: { $method } / { $broad } (auto: { $reason })

## Janelas sobre o mundo
recovery-title = Restaurar a última sessão?
recovery-waits = A simulação espera até você responder.
recovery-restore = Restaurar (R)
recovery-set-aside = Deixar de lado (Esc)
help-title = Teclas e mouse
presets-title = Exemplos
reopen-kept-hover = A caixa livre que este navegador guardou antes de o link abrir.
presets-press = Aperte a tecla ou clique:

## A faixa embaixo do mundo
caption-edited = Antes das alterações: { $caption }
caption-none = Arraste num espaço vazio para lançar um disco; H lista todas as teclas.

## Grandezas, como os campos e as colunas as chamam
quantity-mass = massa
quantity-radius = raio
quantity-vx = v_x
quantity-vy = v_y
quantity-x = x
quantity-y = y
quantity-speed = módulo da velocidade |v|
quantity-direction = direção
direction-hover = Graus a partir da direita, no sentido anti-horário: 0 direita, 90 para cima, 180 esquerda, −90 para baixo

## As abas do painel de baixo
tab-totals = Totais
tab-collisions = Colisões
tab-discs = Discos
tab-speeds = Velocidades
tab-momenta = Vetores p

## Os blocos da tela inicial
tile-head-on = Frontal (1D)
tile-glancing = Oblíqua (2D)
tile-inelastic = Inelástica
tile-pi-blocks = Blocos do π
tile-gas = Um gás
tile-free-play = { scene-untitled }
tile-head-on-blurb = Dois discos se encontram numa linha. A quantidade de movimento total é a mesma depois?
tile-glancing-blurb = Um disco bate em outro fora do centro. Para onde eles vão?
tile-inelastic-blurb = Discos que não quicam de volta por completo. Para onde vai a energia?
tile-pi-blocks-blurb = Um bloco leve, um pesado e uma parede: conte as batidas.
tile-gas-blurb = Muitos discos ao mesmo tempo: como as velocidades se distribuem entre eles?
tile-free-play-blurb = Lance seus próprios discos e mude tudo.
lesson-wall-pause = Pausado: o disco { $disc } bateu na parede { $wall ->
    [left] da esquerda
    [right] da direita
    [bottom] de baixo
   *[top] de cima
}, e o empurrão de uma parede muda a quantidade de movimento total. { $key } continua.

## A tela inicial
close = Fechar
start-title = O que você quer explorar?
start-footer = Tab e Enter escolhem uma lição pelo teclado. Esc mantém a cena que está aberta. O botão Início na barra de cima traz esta tela de volta.

## O painel lateral
controls-for = Os controles para: { $lesson }.
selected-disc-numbered = Disco selecionado ({ $disc })
section-more = Mais
section-more-line = Para discos que giram, e para comparar como o computador faz as contas.
play = Rodar
pause = Pausar
colour-white = brancas
colour-pink = rosa
colour-amber-outlined = âmbar, com contorno
colour-black = pretas
colour-purple = roxas
colour-brown-outlined = marrom, com contorno
show-velocity = setas de velocidade ({ $colour })
show-velocity-hover = onde cada disco vai estar daqui a meio segundo
show-momentum = setas de quantidade de movimento ({ $colour })
show-momentum-hover = quantidade de movimento p = m·v: massa vezes velocidade
show-delta-p = Δp após uma colisão ({ $colour })
show-delta-p-hover = a variação da quantidade de movimento de cada disco, durante um segundo após cada colisão entre discos (em cenas de até { $most } discos: num gás elas esconderiam os discos)
readouts-none = nenhum
readouts-selected = disco selecionado
readouts-all = todos os discos
readouts-label = valores ao lado
readouts-hover = onde os rótulos ficariam uns sobre os outros, alguns discos ficam sem; o mundo mostra quantos
show-center-of-mass = centro de massa
show-center-of-mass-hover = o ponto de equilíbrio de todos os discos, e a sua velocidade
show-safe-palette = cores para daltônicos
show-com-view = vista do centro de massa
show-com-view-hover = a vista se move junto com o centro de massa e as setas mostram as velocidades em relação a ele; o experimento não muda

## A seção Colisões
restitution-label = Choque entre discos, restituição (e)
restitution-scale = 1: voltam por completo, 0: seguem juntos ao longo da linha de impacto
restitution-hover = Quanto da velocidade de aproximação dois discos mantêm ao se afastar, ao longo da linha que passa pelos seus centros: 1 toda, 0 nada (o movimento de lado se mantém)
wall-restitution-label = Choque nas paredes, restituição (e)
wall-restitution-hover = Quanto da sua velocidade em direção a uma parede um disco mantém ao se afastar dela: 1 toda, 0 nada
gravity-label = Gravidade, apontando para baixo
gravity-hover = com que força os discos são puxados para baixo; { $gravity } m/s² na Terra
edges-label = bordas
edges-box = caixa
edges-open = abertas
edges-periodic = periódicas
edges-hover = O que os lados da caixa fazem: caixa, paredes em que os discos quicam; abertas, sem paredes (os discos vão embora); periódicas, um disco que sai por um lado volta pelo outro
time-scale-label = escala de tempo
time-scale-hover = segundos simulados por segundo real: abaixo de 1 é câmera lenta
roughness-hover = Quanto as bordas em contato se agarram numa colisão, fazendo os discos começarem ou pararem de girar: −1 liso (sem aderência, nenhum giro), 0 o deslizamento para, 1 perfeitamente rugoso (o deslizamento se inverte e nenhuma energia se perde)
roughness-label = Aderência entre discos, rugosidade β (−1 liso … 1 rugoso)
wall-roughness-label = Aderência nas paredes, rugosidade β
friction-on-label = O atrito μ limita a aderência
friction-hover = Atrito: a força de lado onde os discos se tocam é no máximo μ vezes a força de frente, então um deslizamento rápido é só freado; ele também faz os discos apoiados uns nos outros se esfregarem. Desligado: sem limite.
friction-label = Atrito μ

## Novos discos e o disco selecionado
new-discs-line = Arraste num espaço vazio para lançar um.
size-follows-mass = tamanho segue a massa (mesma densidade)
size-follows-mass-hover = um disco de 1 kg tem 0,4 m de raio; o raio cresce como √m, para discos novos e ao mudar a massa
radius-from-mass = Raio { $radius } (pela massa)
radius-label = Raio
mass-label = Massa
new-mass-hover = Discos novos pesam de 0,01 a 100 kg: um controle deslizante precisa de duas pontas, e estas chegam a razões de massa de 10 000 para 1. Um disco já na caixa aceita qualquer massa: digite-a na aba Discos ou em Disco selecionado
selected-none = Nenhum: clique num disco para selecioná-lo.
apply = Aplicar
apply-hover = Enter num campo

## As seções Cena e Vista
preset-label = exemplo
preset-choose = abrir um exemplo…
scene-drop = Abra um arquivo de cena: solte-o na página.
scene-file-label = Arquivo de cena:
scene-file-hint = ex.: assets/scenes/preset-8-gas.toml
scene-name-label = Nome:
scene-name-hover = O nome da cena: aparece no alto da janela e dá nome aos arquivos em que ela é salva. Digite um e pressione Enter.
open = Abrir
open-hover = Enter no campo
share = Gerar link
share-hover = coloca esta cena no endereço da página, para enviar como link
saves-download = Salvamentos, exportações e capturas de tela são baixados como arquivos.
saves-go-to = Os salvamentos vão para { $folder }/
ui-scale-label = Tamanho do texto e dos controles
theme-light = Tema claro
theme-dark = Tema escuro
theme-hover = numa sala clara, use o tema claro
language-label = idioma
language-hover = o idioma da janela; os números o acompanham (2,5 ou 2.5)

## Detalhes (em Mais)
method-label = método
method-hover = Como o computador calcula as colisões: auto escolhe; exact encontra cada uma no seu instante; os outros avançam em pequenos intervalos fixos e corrigem as sobreposições
broad-phase-label = fase ampla
broad-phase-hover = Como o computador descobre quais discos estão perto uns dos outros antes de examiná-los de perto: só muda o tempo de cálculo, não o resultado
substeps-label = subpassos
substeps-hover = Em quantos passos menores cada passo de tempo é dividido: mais é mais preciso e mais lento
dt-line = passo de tempo dt = { $dt }
dt-hover = quanto tempo simulado um passo do computador cobre
step-time-line = tempo por passo { $time } (mediana), { $steps } passos no último quadro
fps-line = { $fps } quadros por segundo
sim-rate-line = segundos simulados por segundo real: { $rate }
page-title = Impulse: colisões de discos

## A aba Totais
symbol-ke = Ec
totals-energy = energia
totals-kinetic-energy = energia cinética
totals-momentum = quantidade de movimento
totals-angular-momentum = momento angular L
totals-change = Variação desde t = { $since }: { $p_name } { $momentum }, { $l_name } { $angular }, { $e_name } { $energy }
totals-change-line = Variação desde t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }
totals-change-wrapping = Variação desde t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }; { $l_name } não se conserva quando os discos passam de uma borda para a oposta
totals-none = Nada registrado ainda: rode a simulação.
totals-rotational-ke = Ec de rotação
totals-ke-sum = Ec + Ec de rotação
totals-sum = soma
totals-hover = p: quantidade de movimento, massa vezes velocidade, somada para todos os discos. L: momento angular, o quanto os discos andam em volta do canto inferior esquerdo da caixa (0, 0) e giram. As colisões entre discos conservam os dois; os empurrões das paredes os alteram (linhas tracejadas marcam onde). E: a energia do movimento (Ec) e, com discos girando, também a da rotação.
totals-hover-wrapping = Neste mundo as bordas se ligam: um disco que sai por um lado volta pelo lado oposto. A quantidade de movimento dele não muda, mas a posição dele em relação a (0, 0) salta, então L salta também; não é uma falha das colisões.
totals-walls-push = paredes empurram
axis-time = tempo (s)
axis-energy = energia (J)

## A aba Colisões (o registro)
ledger-pair = discos { $a } e { $b }
ledger-wall = disco { $disc } e a parede { $wall ->
    [left] esquerda
    [right] direita
    [bottom] inferior
   *[top] superior
}
ledger-empty = Nenhuma ainda. Próxima colisão (J) roda até a próxima, entre discos ou com uma parede, e pausa no instante do impacto.
ledger-last = { $count ->
    [one] A última
   *[other] As últimas { $count }, a mais recente primeiro
}
ledger-time-hover = quando aconteceu
ledger-what = o quê
ledger-what-hover = quais discos, ou qual disco e qual parede
ledger-dp-hover = a variação da quantidade de movimento total dos discos envolvidos: zero entre discos, o empurrão da parede numa parede
ledger-dke-hover = a variação da energia cinética deles, a energia do movimento: zero numa colisão elástica, menor que zero quando parte dela se perde
ledger-newest = { $who }, { $when }
ledger-disc-p = disco { $disc }: p (kg·m/s)
ledger-disc-ke = disco { $disc }: { $ke } (J)
ledger-disc-v = disco { $disc }: v { $part } (m/s)
ledger-both-p = os dois discos: p (kg·m/s)
ledger-both-ke = os dois discos: { $ke } (J)
ledger-along-impact = ao longo da linha de impacto
ledger-across-impact = perpendicular a ela
ledger-away-from-wall = para longe da parede
ledger-along-wall = ao longo da parede
ledger-wall-push = o empurrão da parede, Δp (kg·m/s)
ledger-before = antes
ledger-after = depois
ledger-detail-hover = A linha de impacto passa pelos centros dos dois discos (ou vai da parede ao disco) no instante em que eles se tocam; numa colisão sem atrito, só muda a velocidade ao longo dela. Ao longo dela, o sentido positivo vai do disco citado primeiro para o outro (numa parede, para longe da parede).

## A aba Discos
table-spin = rotação ω
    (rad/s)
table-spin-hover = quão rápido o disco gira: radianos por segundo, positivo no sentido anti-horário
table-rotational-ke-hover = a energia da sua rotação, ½·I·ω² com I = ½·m·r²
table-angular-momentum-hover = momento angular, o quanto o disco anda em volta do canto inferior esquerdo da caixa (0, 0) e gira: m·(x·v_y − y·v_x) do seu movimento mais I·ω da sua rotação
table-disc = disco
table-line = Clique numa massa ou velocidade para alterá-la; Enter aplica, Esc cancela.
table-no-discs = Nenhum disco: arraste num espaço vazio para lançar um.

## A fileira de abas do painel e a aba Vetores p
dock-hide = Ocultar
dock-show = Mostrar
dock-no-room = sem espaço aqui: L oculta o painel lateral
dock-no-room-drawer = sem espaço aqui neste tamanho de texto: { $key } muda o tamanho
momenta-no-discs = Nenhum disco.
momenta-too-many = Total: { $total }. Discos demais ({ $count }) para desenhar uma seta para cada; o diagrama desenha até { $most }.
momenta-line = Total (seta grossa): { $total }; a quantidade de movimento de cada disco na sua cor, cada seta começando na ponta da anterior
momenta-hover = { $line }; p_x e p_y são desenhados na mesma escala, então os ângulos são verdadeiros
disc-numbered = disco { $disc }
readout-disc = { $disc }:

## A aba Velocidades
speeds-axis-rim = velocidade, velocidade da borda (m/s)
speeds-axis = velocidade (m/s)
speeds-name = velocidades |v|
speeds-discs = discos
speeds-count = discos em cada barra
# Hovering a bar: how many discs it counts, and its speeds.
speeds-bar = { $count ->
    [one] um disco
   *[other] { $count } discos
} de { $low } a { $high } m/s
maxwell-boltzmann = Maxwell–Boltzmann
rim-speeds = velocidades da borda |ω|·r
rim-speeds-equal = velocidades da borda, divisão igual
speeds-too-few = Poucos discos em movimento para uma distribuição: experimente o exemplo 8, um gás.
speeds-line = Barras: quantos discos se movem com cada velocidade. Curva: como um gás se acomoda (Maxwell–Boltzmann).
speeds-line-few = Barras: quantos discos se movem com cada velocidade. A curva de um gás (Maxwell–Boltzmann) aparece a partir de { $n } discos: experimente o exemplo 8.
speeds-hover = { $line }
    A curva mostra onde as velocidades chegam depois que as colisões repartiram a energia ao acaso, para discos com esta energia cada um, em média: kT = Ec/N = { $kt } (a temperatura, em energia por disco).
speeds-rim-meaning = Barras: quantos discos se movem (ou movem a borda, girando) com cada velocidade. Curvas: onde eles se acomodam quando a energia é repartida igualmente, à temperatura kT = Ec/N = { $kt }: Maxwell–Boltzmann para as velocidades (contínua) e para as velocidades da borda (tracejada).
rim-speeds-hover = Quão rápido a borda de cada disco se move enquanto ele gira: a sua rotação ω vezes o seu raio r.
    { $meaning }
shares-energy = energia:
shares-energy-hover = a parte da energia (%) no movimento e na rotação
shares-moving = movimento
shares-turning = rotação
shares-one-third = um terço
shares-one-third-hover = Repartida igualmente entre as três formas de um disco guardar energia (movendo-se em x, em y, girando), a rotação fica com um terço
shares-moving-ke = movimento (Ec)
shares-turning-ke = rotação (Ec de rotação)

## No mundo
readout-spin = rotação ω = { $spin }   Ec de rotação = { $energy }
readout-angular-momentum = momento angular em relação a (0, 0): L = { $angular }
readouts-culled = { $wanted ->
    [one] sem espaço aqui para os valores do disco selecionado (aproxime com a roda do mouse)
   *[other] valores ao lado de { $shown } de { $wanted } discos: sem espaço para os outros (aproxime com a roda do mouse)
}
launch-no-room = sem espaço aqui
gas-name = Gás de { $count } discos
gas-description = { $count } discos iguais ocupando 30 % de uma caixa periódica (--gas { $count })
tab-edge = Altura da aba
tab-edge-hover = Arraste para deixar a aba mais alta ou mais baixa. Pelo teclado (Tab até aqui): as setas uma linha, Home a mais alta, End a mais baixa, Enter a altura dela; ou clique duplo.
