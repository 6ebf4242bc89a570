import sys, numpy as np
a=np.load(sys.argv[1]); b=np.load(sys.argv[2]); va, vb = sys.argv[3], sys.argv[4]
P=("t_c","y0","z0","vx","vy","vz","speed")
for pt in [k[:-4] for k in a.files if k.endswith("/crb")]:
    if pt+"/crb" not in a: continue
    crb=a[pt+"/crb"]; x=a[f"{pt}/{va}/err"]/crb; y=b[f"{pt}/{vb}/err"]/crb
    d=x-y
    print(pt, f"{va}@{sys.argv[1]} - {vb}@{sys.argv[2]}")
    for k,p in enumerate(P):
        print(f"  {p:<6} rmse {np.sqrt(np.mean(x[:,k]**2)):.3f} -> {np.sqrt(np.mean(y[:,k]**2)):.3f}   diff mean {d[:,k].mean():+.3f} +- {d[:,k].std(ddof=1)/np.sqrt(len(d)):.3f} rms {np.sqrt(np.mean(d[:,k]**2)):.3f}")
