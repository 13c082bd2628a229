# Plots of the accuracy study (docs/accuracy.md). Run by scripts/accuracy.sh:
#   gnuplot -e "data='DIR'; img='IMGDIR'" accuracy_plots.gp
# DIR holds what snow_accuracy wrote (trajectory.dat, scene.dat, floor.gp).
load data.'/floor.gp'
set terminal pngcairo size 1200,520 font 'sans,10'
set grid
set key top right

# 1. Integrators: error versus steps per second and versus cost.
set output img.'/accuracy_integrators.png'
set multiplot layout 1,2 title 'Trajectory error of flakes released at rest (largest over 2 s)'
set logscale xy
set format y '10^{%T}'
set xlabel 'steps per simulated second (1/dt)'
set ylabel 'largest position error (m)'
names = 'euler semi\_implicit exponential rk4 auto'
plot for [i=0:4] data.'/trajectory.dat' index i using 1:2 with linespoints lw 2 pt 7 title word(names, i+1)
set xlabel 'CPU ns per flake per simulated second'
plot for [i=0:4] data.'/trajectory.dat' index i using 3:2 with linespoints lw 2 pt 7 title word(names, i+1)
unset multiplot
unset logscale
set format y '%g'

# 2. Scene: depth error versus CPU ms per simulated second, with the front and presets.
set output img.'/accuracy_scene.png'
set title 'Village depth field after the snowfall: error versus cost'
set xlabel 'CPU ms per simulated second (one thread)'
set ylabel 'rel L1 of the depth field (blocks)'
set logscale x
set key outside right
plot data.'/scene.dat' index 5 using 2:3 with points pt 6 ps 1.2 lc rgb '#999999' title 'dt × cell × occlusion grid', \
     data.'/scene.dat' index 0 using 2:3 with points pt 7 ps 1.2 title 'dt sweep', \
     data.'/scene.dat' index 2 using 2:3 with points pt 5 ps 1.2 title 'cell size sweep', \
     data.'/scene.dat' index 3 using 2:3 with points pt 9 ps 1.2 title 'smoothing sweep', \
     data.'/scene.dat' index 4 using 2:3 with points pt 11 ps 1.2 title 'occlusion sweep', \
     data.'/scene.dat' index 6 using 2:3 with steps lw 2 lc rgb '#000000' title 'Pareto front', \
     data.'/scene.dat' index 7 using 2:3:5 with labels offset 0,1.2 point pt 3 ps 2 lc rgb '#cc0000' notitle, \
     noise_floor with lines dt 2 lc rgb '#0000cc' title 'noise floor', \
     noise_floor * tol_high with lines dt 3 lc rgb '#3333cc' title 'high limit', \
     noise_floor * tol_medium with lines dt 3 lc rgb '#6666cc' title 'medium limit', \
     noise_floor * tol_low with lines dt 3 lc rgb '#9999cc' title 'low limit'

# 3. The same against CPU ms per tick, coloured by steps per second.
set output img.'/accuracy_scene_tick.png'
set title 'Village depth field after the snowfall: error versus CPU ms per tick'
set xlabel 'CPU ms per tick (one thread)'
unset logscale x
set key outside right
steps = '15 30 60 120 240'
plot for [i=1:5] data.'/scene.dat' index 5 using 1:($4 == word(steps, i)+0 ? $3 : 1/0) with points pt 7 ps 1.2 lc i title 'grid, dt 1/'.word(steps, i), \
     for [i=1:5] data.'/scene.dat' index 0 using 1:($4 == word(steps, i)+0 ? $3 : 1/0) with points pt 5 ps 1.6 lc i title 'dt sweep, dt 1/'.word(steps, i), \
     noise_floor with lines dt 2 lc rgb '#0000cc' title 'noise floor'

# 4. Wind field: error of the mean wind versus the field's cost.
set output img.'/accuracy_wind_field.png'
set title 'Wind field: time-mean wind near the ground against the fine field, versus its cost'
set xlabel 'wind_field ms per simulated second (one thread)'
set ylabel 'rel L1 of the mean wind'
set logscale x
set key outside right
plot data.'/wind_field.dat' index 0 using 1:2:3 with labels offset 0,1 point pt 7 ps 1.4 lc rgb '#cc0000' title 'cells (update every 4)', \
     data.'/wind_field.dat' index 1 using 1:2:3 with labels offset 0,-1 point pt 5 ps 1.4 lc rgb '#0000cc' title 'update_every (64×16×64)'
