"""The re-run reference campaign on the converged truth (data/reference/truth2_*/): per wall and
boundary, mean +- SD over the seeds of each run's summary.json. Run from the repository root."""
import json, glob, statistics as st, sys
groups={}
for f in sorted(glob.glob('data/reference/truth2_*/runs/*/summary.json')):
    name=f.split('/')[-2]; wall,seed,bc=name.split('_',2)
    s=json.load(open(f)); groups.setdefault((wall,bc),[]).append(s)
def ms(v): 
    v=[x for x in v if x is not None]
    return '%.3f +- %.3f'%(st.mean(v), st.stdev(v)) if len(v)>1 else ('%.3f'%v[0] if v else '-')
print('| wall | boundary | runs | peak friction | residual friction | total dilation (mm) | wall slip | band (d50, last 2 mm) | shear mode |')
print('|---|---|---|---|---|---|---|---|---|')
for (w,bc),ss in groups.items():
    print('| %s | %s | %d | %s | %s | %s | %s | %s | %s |'%(w,bc,len(ss),ms([s['peak_friction'] for s in ss]),ms([s['residual_friction'] for s in ss]),ms([s['dilation_mm'] for s in ss]),ms([s['wall_slip'] for s in ss]),ms([s.get('band_thickness_d50') for s in ss]),', '.join(s['shear_mode'] for s in ss)))
