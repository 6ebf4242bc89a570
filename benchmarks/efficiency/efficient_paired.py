"""The bound-efficient (linearised, everything known) V.x error of a trial's noise draw: F^-1 G^T W (image - expectation)."""
import sys, math, numpy as np
sys.path.insert(0, __import__('os').path.join(__import__('os').path.dirname(__file__), '..'))
from bench_efficiency import _spec
from ballscan.lab import experiments as ex
from ballscan.model.render import render
from ballscan.solve.precision import _pixel_model, _n_lines_for
from ballscan.model.averaged import averaged_model
f,v=sys.argv[1],float(sys.argv[2]); trials=[int(x) for x in sys.argv[3].split(",")]
out=[]
for k in trials:
    spec=_spec(f,v,k); st=np.random.SeedSequence(spec.seed).generate_state(3,dtype=np.uint32)
    ph=float(st[1])/2**32-0.5; g=ex.scene_geometry(spec.scene,ph); cam=spec.scene.camera; m=g.motion; nse=spec.scene.noise
    rd=render(cam,(m,ex.appearance(spec.scene,"none",int(st[2]))),g.n_lines,background_level=spec.scene.background_level,noise=nse,seed=int(st[0]))
    cov,dcov=_pixel_model(cam,m,32)
    nl=_n_lines_for(cam,m); tt=np.arange(nl)/cam.line_rate_hz
    me=averaged_model(cam,m.to_params()[None],m.radius_m,tt,m.acceleration_mps2,8)
    rows=np.flatnonzero(me.presence[0]>0)
    lo=np.nanmin(me.left_px[0,rows]); c0=math.floor(lo)-2; cols=np.arange(c0,c0+cov.shape[1])
    gain=rd.column_gain[cols]
    expect=nse.black_dn+nse.white_dn*gain[None,:]*rd.clean[np.ix_(rows,cols)]
    e=rd.image[np.ix_(rows,cols)].astype(float)-expect
    dy=spec.scene.ball_level-spec.scene.background_level
    y=spec.scene.background_level+dy*cov
    var=nse.read_dn**2+1/12+y*nse.white_dn**2/nse.full_well_e
    G=nse.white_dn*dy*dcov*gain[None,None,:]
    F=np.einsum("pnc,qnc->pq",G/var,G); C=np.linalg.inv(F)
    d=C@np.einsum("pnc,nc->p",G/var,e)
    out.append(d[3]/math.sqrt(C[3,3]))
    print(k, f"efficient V.x error {d[3]/math.sqrt(C[3,3]):+.2f} sigma", flush=True)
print("rms", np.sqrt(np.mean(np.square(out))))
