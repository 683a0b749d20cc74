" Vim syntax file for rts scene files (docs/language.md). The word lists are the language's
" reserved words, its block kinds (SceneBuilder::block_kinds) and its builtins
" (runtime::builtin_table); tests/lsp/test_editor_words.cpp checks them against those tables.
if exists("b:current_syntax") | finish | endif

syn keyword rtsKeyword let macro return include with
syn keyword rtsConditional if else
syn keyword rtsRepeat for in while break continue step
syn keyword rtsOperator and or not
syn keyword rtsTransform translate rotate scale matrix
syn keyword rtsBoolean true false
syn keyword rtsConstant none clock frame frames

" Block kinds.
syn keyword rtsBlock settings camera material checker stripes gradient image_texture latlong_map cube_map sky_sphere
syn keyword rtsBlock bozo spotted granite marble wood agate onion leopard wrinkles crackle cells bumps dents radial spiral1 spiral2 boxed cylindrical planar spherical
syn keyword rtsBlock ripples waves pattern
syn keyword rtsBlock box cone cylinder disc mesh plane quad sphere superellipsoid torus triangle isosurface blob height_field sor lathe prism poly
syn keyword rtsBlock point_light spot_light directional_light area_light group union intersection difference merge clip text

" Builtins (only where called).
syn match rtsBuiltin "\<\(sin\|cos\|tan\|asin\|acos\|atan\|atan2\|sqrt\|pow\|exp\|log\|abs\|floor\|ceil\|round\|radians\|degrees\|min\|max\|clamp\|mix\|dot\|cross\|length\|normalize\|rgb\|vec\|len\|select\|append\|with_item\|str\|format\|print\|assert\|error\|checker\|stripes\|gradient\|image_texture\|noise\|fbm\|turbulence\|vturbulence\|cells\|worley\|random\|rand\|identity\|vrotate\|vaxis_rotate\|distance\|smoothstep\|spline\|trace\|vlength\|vnormalize\|vdot\|vcross\|lerp\)\>\ze\s*("

" A property: `name =` (not `==`).
syn match rtsProperty "\<\h\w*\>\ze\s*=[^=]"

syn match rtsNumber "\<\d\+\(\.\d*\)\=\([eE][+-]\=\d\+\)\=\>"
syn match rtsNumber "\.\d\+\([eE][+-]\=\d\+\)\=\>"
syn match rtsEscape contained "\\\([ntr\\"0]\|u{\x\+}\)"
syn region rtsString start=+"+ skip=+\\\\\|\\"+ end=+"+ oneline contains=rtsEscape
syn keyword rtsTodo contained TODO FIXME XXX NOTE
syn match rtsLineComment "//.*$" contains=rtsTodo,@Spell
syn region rtsBlockComment start="/\*" end="\*/" contains=rtsTodo,@Spell

hi def link rtsKeyword Keyword
hi def link rtsConditional Conditional
hi def link rtsRepeat Repeat
hi def link rtsOperator Operator
hi def link rtsTransform Statement
hi def link rtsBoolean Boolean
hi def link rtsConstant Constant
hi def link rtsBlock Type
hi def link rtsBuiltin Function
hi def link rtsProperty Identifier
hi def link rtsNumber Number
hi def link rtsString String
hi def link rtsEscape SpecialChar
hi def link rtsTodo Todo
hi def link rtsLineComment Comment
hi def link rtsBlockComment Comment

let b:current_syntax = "rts"
