# Acesso pelo teclado, som e leitor de tela: o que a janela diz sobre eles.

select-no-discs = Nenhum disco para selecionar: Enter coloca um no centro.
selected-disc-said = Disco { $disc } de { $discs } selecionado: { $mass }; velocidade { $velocity }
launched-at-centre = Disco { $disc } em repouso no centro: com a simulação pausada, as teclas de seta definem a velocidade dele
launched-near-centre = Disco { $disc } em repouso ao lado do disco { $beside } (o centro estava ocupado): com a simulação pausada, as teclas de seta definem a velocidade dele

## O caminho pelo teclado (linhas da ajuda)
keys-focus = Tab / Shift+Tab
help-focus = percorre os controles, na ordem de leitura; Espaço ou Enter aciona um, as teclas de seta movem um controle deslizante, escolhem numa lista suspensa ou rolam uma lista (também Page Up, Page Down, Home e End); Esc ou um clique no mundo reativa os atalhos de teclado
keys-regions = F6 / Shift+F6
help-regions = pular para a próxima parte da janela: os controles (abertos se estiverem fechados; primeiro a massa do disco selecionado), as abas, a barra de cima e de volta ao mundo; depois Tab avança dentro dela
keys-aim-keys = Teclas de seta, em pausa, com um disco selecionado
help-aim-keys = mira o disco: a velocidade dele ±0,1 m/s a cada toque (Shift: ±1 m/s)
keys-select-next = Q / Shift+Q
help-select-next = seleciona o disco seguinte / o anterior
keys-launch-centre = Enter
help-launch-centre = um disco novo em repouso no centro da vista, já selecionado; numa lição parada na sua pergunta, põe para rodar
keys-in-panels = As teclas agora agem nos controles: Esc ou um clique no mundo reativa os atalhos de teclado.
keys-in-panels-short = Esc: reativar os atalhos
keys-tab-edge = Altura da aba: setas uma linha, Home a mais alta, End a mais baixa, Enter a dela. Esc: reativar os atalhos.
keys-tab-edge-short = Setas, Home, End: altura da aba
keys-after-field = Espaço, N e J agem na simulação; os outros atalhos esperam: Esc ou um clique no mundo os reativa.

## Som
keys-sound = F8
help-sound = som ligado / desligado: um clique a cada impacto, mais alto quanto mais forte ele for, mais agudo entre discos do que numa parede (em silêncio quando pausado ou mais rápido que ×2)
label-toggle-sound = Som
sound-on = Som ligado: um clique a cada impacto (em silêncio quando pausado ou mais rápido que ×2)
sound-off = Som desligado

## Dito a um leitor de tela (a região ao vivo do navegador, a aba Narração)
said-pair = Disco { $a } bateu no disco { $b }: quantidade de movimento total antes { $before }, depois { $after }
said-wall = Disco { $disc } bateu na parede { $wall ->
    [left] esquerda
    [right] direita
    [bottom] inferior
   *[top] superior
 }: velocidade antes { $before }, depois { $after }
place-middle = no meio
place-left = à esquerda
place-right = à direita
place-bottom = embaixo
place-top = em cima
place-bottom-left = embaixo à esquerda
place-bottom-right = embaixo à direita
place-top-left = em cima à esquerda
place-top-right = em cima à direita
motion-rest = em repouso
motion-moving = movendo-se { $direction } a { $speed }
direction-right = para a direita
direction-up-right = para cima e para a direita
direction-up = para cima
direction-up-left = para cima e para a esquerda
direction-left = para a esquerda
direction-down-left = para baixo e para a esquerda
direction-down = para baixo
direction-down-right = para baixo e para a direita
describe-box = { $discs ->
    [one] { $discs } disco
   *[other] { $discs } discos
 } { $edges ->
    [open] num espaço de { $width } por { $height } metros, sem paredes.
    [periodic] num espaço de { $width } por { $height } metros cujos lados se unem (um disco que sai por um lado volta pelo outro).
   *[box] numa caixa de { $width } por { $height } metros.
 }
describe-gravity = Gravidade de { $gravity }, apontando para baixo.
describe-no-gravity = Sem gravidade.
describe-restitution = Coeficiente de restituição entre discos: { $restitution }.
describe-disc = Disco { $disc }: { $mass }; { $place }; { $motion }.
describe-more = E mais { $more ->
    [one] { $more } disco
   *[other] { $more } discos
 }; a velocidade média deles é { $speed }.
describe-totals = { $state ->
    [paused] Pausado
   *[running] Rodando
 } em t = { $time }; quantidade de movimento total { $momentum }, energia cinética { $energy }.
tab-words = Narração
# On the desktop; in the browser, where a screen reader reads the page.
words-line = O que acontece, em palavras, do mais recente ao mais antigo: no máximo uma colisão a cada { $gap } s (a aba { tab-collisions } lista todas).
words-line-web = O que acontece, em palavras, do mais recente ao mais antigo, como um leitor de tela lê: no máximo uma colisão a cada { $gap } s (a aba { tab-collisions } lista todas).
words-none = Nada foi dito ainda.
label-describe = Descrever a cena
mirror-title = Impulse: controles para teclado e leitores de tela
mirror-canvas = Impulse, a simulação: { $keys } mostra as teclas
mirror-said = O que acontece
