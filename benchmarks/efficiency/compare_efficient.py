import numpy as np, re, sys
pt, files = sys.argv[1], sys.argv[2:4]
eff={}
for fn in files:
    for line in open(fn):
        m=re.match(r"(\d+) efficient V.x error ([-+.\d]+)",line)
        if m: eff[int(m.group(1))]=float(m.group(2))
e=np.array([eff[k] for k in range(128)])
for npz in sys.argv[4:]:
    d=np.load(npz); crb=d[pt+"/crb"]; fit=d[pt+"/default/err"][:,3]/crb[3]
    print(npz, "efficient-lin RMS", np.sqrt(np.mean(e**2)).round(3), "fit RMS", np.sqrt(np.mean(fit**2)).round(3),
      "corr", np.corrcoef(e,fit)[0,1].round(3), "RMS(fit-eff)", np.sqrt(np.mean((fit-e)**2)).round(3), "mean(fit-eff)", (fit-e).mean().round(3),
      "slope", np.polyfit(e,fit,1)[0].round(3), "var diff", np.var(fit-e).round(3), "2cov", (2*np.cov(e,fit-e)[0,1]).round(3))
